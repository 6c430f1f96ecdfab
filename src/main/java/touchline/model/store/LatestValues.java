package touchline.model.store;

import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Message;
import touchline.proto.Fumanoid;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The newest value of every robot's debug option (tables, regions, grids, positions, field
 * objects, images, text, plots): views showing "the current picture" read only this, so
 * memory is one message per robot and option however fast the robot sends. Plot history
 * lives in {@link PlotStore}, text history in {@link TextLog}.
 */
public final class LatestValues implements EnvelopeSink {

    /** Key of one robot's option. */
    public record Key(int robotId, String option) { }

    private final Map<Key, Latest> latest = new ConcurrentHashMap<>();
    private final AtomicLong version = new AtomicLong();

    @Override
    public void accept(Envelope e) {
        if (e.direction() != Direction.IN || e.robotId() < 0 || !(e.message() instanceof Fumanoid.Message m)) {
            return;
        }
        for (Map.Entry<FieldDescriptor, Object> f : m.getAllFields().entrySet()) {
            if (f.getKey().isExtension() && f.getValue() instanceof Message data) {
                String option = optionOf(data);
                if (option != null) {
                    latest.put(new Key(e.robotId(), option),
                            new Latest(e.robotId(), option, e.kind(), data, e.timeMicros(), version.incrementAndGet()));
                }
            }
        }
    }

    /** The {@code option} string field that every data message carries by convention. */
    static String optionOf(Message data) {
        FieldDescriptor name = data.getDescriptorForType().findFieldByName("option");
        if (name != null && name.getType() == FieldDescriptor.Type.STRING && data.hasField(name)) {
            return (String) data.getField(name);
        }
        return null;
    }

    public Optional<Latest> get(int robotId, String option) {
        return Optional.ofNullable(latest.get(new Key(robotId, option)));
    }

    /** Every robot's newest value of messages of one kind (e.g. {@code fieldObjects}). */
    public List<Latest> ofKind(String kind) {
        List<Latest> out = new ArrayList<>();
        for (Latest l : latest.values()) {
            if (l.kind().equals(kind)) {
                out.add(l);
            }
        }
        return out;
    }

    public long version() {
        return version.get();
    }
}
