package touchline.protocol.ros2;

import org.json.JSONArray;
import org.json.JSONException;
import org.json.JSONObject;
import org.json.JSONTokener;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * Decodes a {@code json} channel's messages (with a {@code jsonschema} schema or none) into
 * the same tree as CDR: one UTF-8 JSON object per message, its fields in name order (the JSON
 * library keeps no order; a stable one keeps CSV columns and plots the same from message to
 * message). The schema is not needed to read the values (JSON names them), so it is not
 * enforced. Objects nest at most {@link RosMessage#MAX_DEPTH} deep.
 */
public final class JsonDecoder implements MessageDecoder {

    private final String typeName;

    /** {@code typeName}: the schema's name, or the topic when the channel has no schema. */
    public JsonDecoder(String typeName) {
        this.typeName = typeName;
    }

    @Override
    public String typeName() {
        return typeName;
    }

    @Override
    public DecodeResult decode(byte[] data, int offset, int length) {
        if (offset < 0 || length < 0 || offset > data.length - length) {
            return new DecodeResult.Undecodable("no message: " + length + " bytes from " + offset + " of " + data.length);
        }
        String text = new String(data, offset, length, StandardCharsets.UTF_8);
        try {
            JSONTokener tokens = new JSONTokener(text);
            Object value = tokens.nextValue();
            if (!(value instanceof JSONObject o)) {
                return new DecodeResult.Undecodable("the JSON message is not an object");
            }
            if (tokens.nextClean() != 0) {
                return new DecodeResult.Undecodable("text after the JSON object");
            }
            return new DecodeResult.Decoded(object(typeName, o, 0));
        } catch (JSONException e) {
            return new DecodeResult.Undecodable("not JSON: " + MsgParser.cut(String.valueOf(e.getMessage())));
        } catch (TooDeep e) {
            return new DecodeResult.Undecodable("the JSON message nests deeper than " + RosMessage.MAX_DEPTH + " levels");
        }
    }

    private static final class TooDeep extends Exception {
        TooDeep() {
            super(null, null, false, false);
        }
    }

    private static RosMessage object(String type, JSONObject o, int depth) throws TooDeep {
        if (depth >= RosMessage.MAX_DEPTH) {
            throw new TooDeep();
        }
        List<String> names = new ArrayList<>(o.keySet());
        names.sort(null);
        Object[] values = new Object[names.size()];
        for (int i = 0; i < values.length; i++) {
            values[i] = value(o.opt(names.get(i)), depth);
        }
        return new RosMessage(type, null, names.toArray(new String[0]), values);
    }

    private static Object value(Object v, int depth) throws TooDeep {
        if (v instanceof JSONObject o) {
            return object("", o, depth + 1);
        }
        if (v instanceof JSONArray a) {
            if (depth + 1 >= RosMessage.MAX_DEPTH) {
                throw new TooDeep();
            }
            Object[] out = new Object[a.length()];
            for (int k = 0; k < out.length; k++) {
                out[k] = value(a.opt(k), depth + 1);
            }
            return out;
        }
        if (v instanceof Integer || v instanceof Long || v instanceof java.lang.Short || v instanceof Byte) {
            return ((Number) v).longValue();
        }
        if (v instanceof BigInteger b) {
            return b.bitLength() < 64 ? (Object) b.longValue() : (Object) b.doubleValue();
        }
        if (v instanceof BigDecimal || v instanceof Double || v instanceof Float) {
            return ((Number) v).doubleValue();
        }
        if (v == JSONObject.NULL) {
            return null;
        }
        return v; // Boolean, String
    }
}
