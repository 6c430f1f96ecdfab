package touchline.record;

import com.google.protobuf.DescriptorProtos.FileDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorSet;
import com.google.protobuf.Descriptors.DescriptorValidationException;
import com.google.protobuf.Descriptors.FileDescriptor;
import com.google.protobuf.InvalidProtocolBufferException;
import touchline.proto.Fumanoid;
import touchline.proto.Nao;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Protobuf file descriptors known at run time: Touchline's own (compiled in) plus those a
 * team loads from a {@code protoc --descriptor_set_out} file or finds embedded in a
 * recording. Files the console was compiled with are resolved to the compiled descriptors,
 * so a team's extensions of {@code fumanoid.Message} extend the very type the decoder uses.
 * Also builds the self-contained FileDescriptorSets that MCAP schemas carry.
 */
public final class SchemaSet {

    /**
     * How deep imports may nest. Real schemas nest a handful of levels; a recording from
     * outside could nest thousands, and resolving them recursively would overflow the stack.
     */
    static final int MAX_IMPORT_DEPTH = 100;

    private final Map<String, FileDescriptor> files = new LinkedHashMap<>();

    public SchemaSet() {
        files.put(Fumanoid.getDescriptor().getName(), Fumanoid.getDescriptor());
        files.put(Nao.getDescriptor().getName(), Nao.getDescriptor());
    }

    /** Loads a protoc descriptor set file; returns the files it added. */
    public List<FileDescriptor> load(Path descriptorSet) throws RecordingException {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(descriptorSet);
        } catch (IOException e) {
            throw new RecordingException("cannot read descriptor set " + descriptorSet + ": " + e.getMessage());
        }
        try {
            return add(FileDescriptorSet.parseFrom(bytes));
        } catch (InvalidProtocolBufferException e) {
            throw new RecordingException(descriptorSet.getFileName() + " is not a protobuf descriptor set "
                    + "(make one with protoc --include_imports --descriptor_set_out=FILE): " + e.getMessage());
        }
    }

    /**
     * Adds every file of {@code set} not known yet, dependencies first. Throws with a
     * user-facing message when a file does not build (missing import, bad type reference).
     */
    public synchronized List<FileDescriptor> add(FileDescriptorSet set) throws RecordingException {
        Map<String, FileDescriptorProto> pending = new LinkedHashMap<>();
        for (FileDescriptorProto p : set.getFileList()) {
            if (!files.containsKey(p.getName())) {
                pending.put(p.getName(), p);
            }
        }
        List<FileDescriptor> added = new ArrayList<>();
        for (String name : new ArrayList<>(pending.keySet())) {
            build(name, pending, added, new java.util.LinkedHashSet<>(), null);
        }
        return added;
    }

    private FileDescriptor build(String name, Map<String, FileDescriptorProto> pending, List<FileDescriptor> added,
                                 java.util.LinkedHashSet<String> path, String importer) throws RecordingException {
        FileDescriptor known = files.get(name);
        if (known != null) {
            return known;
        }
        FileDescriptorProto proto = pending.get(name);
        if (proto == null) {
            throw new RecordingException("schema file " + importer + " imports " + name
                    + ", which is neither in the descriptor set nor known to Touchline");
        }
        if (path.contains(name)) {
            throw new RecordingException("schema files import each other in a cycle: " + path);
        }
        if (path.size() >= MAX_IMPORT_DEPTH) {
            throw new RecordingException("schema file " + name + " is imported through more than " + MAX_IMPORT_DEPTH
                    + " levels of imports; such a schema is not loaded");
        }
        path.add(name);
        List<FileDescriptor> deps = new ArrayList<>();
        for (String dep : proto.getDependencyList()) {
            deps.add(build(dep, pending, added, path, name));
        }
        path.remove(name);
        try {
            FileDescriptor file = FileDescriptor.buildFrom(proto, deps.toArray(new FileDescriptor[0]));
            files.put(name, file);
            added.add(file);
            return file;
        } catch (DescriptorValidationException e) {
            throw new RecordingException("schema file " + name + " does not build: " + e.getMessage());
        } catch (RuntimeException e) {
            // protobuf-java trusts some parts of a descriptor it does not validate (a field without a
            // type throws a NullPointerException while linking): from outside, that is a broken schema
            throw new RecordingException("schema file " + name + " does not build: " + e);
        }
    }

    public synchronized Collection<FileDescriptor> files() {
        return List.copyOf(files.values());
    }

    /** Files added beyond the compiled-in ones (a team's own types). */
    public synchronized List<FileDescriptor> teamFiles() {
        return files.values().stream()
                .filter(f -> f != Fumanoid.getDescriptor() && f != Nao.getDescriptor())
                .toList();
    }

    /** {@code roots} and everything they import, dependencies first: what an MCAP protobuf schema holds. */
    public static FileDescriptorSet descriptorSet(Collection<FileDescriptor> roots) {
        Map<String, FileDescriptorProto> out = new LinkedHashMap<>();
        for (FileDescriptor root : roots) {
            collect(root, out);
        }
        return FileDescriptorSet.newBuilder().addAllFile(out.values()).build();
    }

    private static void collect(FileDescriptor file, Map<String, FileDescriptorProto> out) {
        if (out.containsKey(file.getName())) {
            return;
        }
        for (FileDescriptor dep : file.getDependencies()) {
            collect(dep, out);
        }
        out.put(file.getName(), file.toProto());
    }
}
