package touchline.transport.nao;

import java.util.List;
import java.util.Objects;

/**
 * One NAOqi method call to make: {@code module.method(params)} with plain Java parameter
 * values (see {@link touchline.protocol.nao.MixedValueCodec}).
 */
public record NaoCall(String module, String method, List<Object> params) {

    public NaoCall {
        Objects.requireNonNull(module, "module");
        Objects.requireNonNull(method, "method");
        params = params == null ? List.of() : java.util.Collections.unmodifiableList(new java.util.ArrayList<>(params));
    }

    public static NaoCall of(String module, String method, Object... params) {
        return new NaoCall(module, method, java.util.Arrays.asList(params));
    }

    /** Parses {@code Module.method}; throws IllegalArgumentException with a clear message otherwise. */
    public static NaoCall parse(String qualifiedMethod, List<Object> params) {
        int dot = qualifiedMethod.lastIndexOf('.');
        if (dot <= 0 || dot == qualifiedMethod.length() - 1) {
            throw new IllegalArgumentException("expected Module.method, got '" + qualifiedMethod + "'");
        }
        return new NaoCall(qualifiedMethod.substring(0, dot), qualifiedMethod.substring(dot + 1), params);
    }

    public String qualifiedName() {
        return module + "." + method;
    }

    @Override
    public String toString() {
        return qualifiedName() + params;
    }
}
