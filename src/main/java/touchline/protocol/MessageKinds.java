package touchline.protocol;

import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.DynamicMessage;
import com.google.protobuf.ExtensionRegistry;
import com.google.protobuf.Descriptors.FileDescriptor;
import touchline.proto.Fumanoid;

import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The registry of {@code Message} extensions: extension number to name and type. Holds the
 * ones Touchline defines and any a team loads at run time from its own {@code .proto}
 * descriptors, so their messages decode without recompiling. Thread-safe: teams' types may be
 * added while datagrams are being decoded.
 */
public final class MessageKinds {

    /** Extension numbers reserved for teams' own messages (documented in docs/protocol.md). */
    public static final int TEAM_RANGE_FIRST = 1000;
    public static final int TEAM_RANGE_LAST = 1999;

    private volatile ExtensionRegistry registry;
    private final Map<Integer, FieldDescriptor> byNumber = new ConcurrentHashMap<>();
    private final Map<String, FieldDescriptor> byName = new ConcurrentHashMap<>();
    // One String instance per kind: every Envelope of a kind shares it, so its hash is computed once
    private final Map<Integer, String> names = new ConcurrentHashMap<>();

    public MessageKinds() {
        ExtensionRegistry r = ExtensionRegistry.newInstance();
        Fumanoid.registerAllExtensions(r);
        registry = r;
        for (FieldDescriptor ext : Fumanoid.getDescriptor().getExtensions()) {
            byNumber.put(ext.getNumber(), ext);
            byName.put(ext.getName(), ext);
        }
    }

    /**
     * Adds every extension of {@code Message} declared in {@code file} (a team's own types).
     * An extension whose number is taken already is refused with the reason returned.
     */
    public Optional<String> add(FileDescriptor file) {
        return Optional.ofNullable(add(List.of(file)).get(file));
    }

    /**
     * Adds every extension of {@code Message} declared in {@code files}; returns the reason for
     * each file one of whose extensions was refused (its number taken already). The registry is
     * built anew once per call, and only when something was added: a schema of thousands of
     * files costs one build, not one per file.
     */
    public synchronized Map<FileDescriptor, String> add(Collection<FileDescriptor> files) {
        Map<FileDescriptor, String> refusals = new LinkedHashMap<>();
        boolean added = false;
        for (FileDescriptor file : files) {
            StringBuilder refused = new StringBuilder();
            for (FieldDescriptor ext : file.getExtensions()) {
                if (!ext.getContainingType().getFullName().equals(Fumanoid.Message.getDescriptor().getFullName())) {
                    continue;
                }
                FieldDescriptor taken = byNumber.get(ext.getNumber());
                if (taken != null && !taken.getFullName().equals(ext.getFullName())) {
                    refused.append("extension ").append(ext.getNumber()).append(" (").append(ext.getFullName())
                            .append(") is taken by ").append(taken.getFullName()).append("; ");
                    continue;
                }
                byNumber.put(ext.getNumber(), ext);
                byName.put(ext.getName(), ext);
                names.put(ext.getNumber(), ext.getName()); // was perhaps "ext#N" until now
                added = true;
            }
            if (refused.length() > 0) {
                refusals.put(file, refused.toString().trim());
            }
        }
        if (added) {
            ExtensionRegistry r = ExtensionRegistry.newInstance();
            Fumanoid.registerAllExtensions(r);
            for (FieldDescriptor known : byNumber.values()) {
                if (!known.getFile().equals(Fumanoid.getDescriptor())) {
                    addDynamic(r, known);
                }
            }
            registry = r; // readers decoding meanwhile keep the registry they took
        }
        return refusals;
    }

    private static void addDynamic(ExtensionRegistry r, FieldDescriptor ext) {
        if (ext.getJavaType() == FieldDescriptor.JavaType.MESSAGE) {
            r.add(ext, DynamicMessage.getDefaultInstance(ext.getMessageType()));
        } else {
            r.add(ext);
        }
    }

    public ExtensionRegistry registry() {
        return registry;
    }

    public Optional<FieldDescriptor> byNumber(int number) {
        return Optional.ofNullable(byNumber.get(number));
    }

    public Optional<FieldDescriptor> byName(String name) {
        return Optional.ofNullable(byName.get(name));
    }

    /** The kind name shown to users and used for channels: the extension's name, or {@code ext#N}. */
    public String kindOf(int extensionNumber) {
        String name = names.get(extensionNumber);
        if (name == null) {
            FieldDescriptor d = byNumber.get(extensionNumber);
            name = d != null ? d.getName() : unknownKind(extensionNumber);
            if (d != null || names.size() < 4096) { // unknown numbers from bad input must not grow it without bound
                names.put(extensionNumber, name);
            }
        }
        return name;
    }

    public static String unknownKind(int extensionNumber) {
        return "ext#" + extensionNumber;
    }
}
