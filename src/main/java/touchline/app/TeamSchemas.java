package touchline.app;

import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Descriptors.FileDescriptor;
import touchline.proto.Fumanoid;
import touchline.protocol.MessageKinds;
import touchline.record.RecordingException;
import touchline.record.SchemaSet;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * A team's own message types loaded at run time from a protoc descriptor set: the files are
 * built onto the compiled FUmanoids types and their {@code Message} extensions handed to the
 * console's {@link MessageKinds}, which then decodes them by name. Remembers what was loaded
 * and what was refused, for the view to list. The console owns one
 * ({@link Console#teamSchemas()}), the one way to load them: the replay view, {@code record --proto}
 * and {@code serve --proto} ask it, never the kinds.
 */
public final class TeamSchemas {

    /** What one descriptor set brought: extensions now decoded, and what was refused and why. */
    public record Outcome(Path file, List<String> extensions, List<String> refusals) { }

    private final SchemaSet schemas = new SchemaSet();
    private final MessageKinds kinds;

    public TeamSchemas(MessageKinds kinds) {
        this.kinds = kinds;
    }

    /** Loads {@code file}; throws with a user-facing message when it is not a usable descriptor set. */
    public synchronized Outcome load(Path file) throws RecordingException {
        List<FileDescriptor> added = schemas.load(file);
        List<String> extensions = new ArrayList<>();
        List<String> refusals = new ArrayList<>();
        if (added.isEmpty()) {
            refusals.add(file.getFileName() + ": nothing new (its files are loaded already)");
        }
        Map<FileDescriptor, String> refusedByFile = kinds.add(added);
        for (FileDescriptor f : added) {
            String refused = refusedByFile.getOrDefault(f, "");
            if (!refused.isEmpty()) {
                refusals.add(f.getName() + ": " + refused);
            }
            int before = extensions.size();
            for (FieldDescriptor ext : f.getExtensions()) {
                boolean ofMessage = ext.getContainingType().getFullName()
                        .equals(Fumanoid.Message.getDescriptor().getFullName());
                if (ofMessage && !refused.contains("(" + ext.getFullName() + ")")) {
                    extensions.add(ext.getName() + " = " + ext.getNumber() + "  (" + typeName(ext) + ", " + f.getName() + ")");
                }
            }
            if (extensions.size() == before && refused.isEmpty()) {
                refusals.add(f.getName() + ": declares no extension of fumanoid.Message (nothing new to decode)");
            }
        }
        return new Outcome(file, extensions, refusals);
    }

    /** The team's own files loaded so far (beyond the compiled-in ones), for a recording to embed. */
    public synchronized List<FileDescriptor> teamFiles() {
        return schemas.teamFiles();
    }

    private static String typeName(FieldDescriptor ext) {
        return ext.getJavaType() == FieldDescriptor.JavaType.MESSAGE ? ext.getMessageType().getFullName()
                : ext.getType().name().toLowerCase(java.util.Locale.ROOT);
    }
}
