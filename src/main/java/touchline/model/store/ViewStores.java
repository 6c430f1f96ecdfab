package touchline.model.store;

import com.google.protobuf.Message;
import touchline.proto.Fumanoid;
import touchline.protocol.DebugData;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.util.function.BooleanSupplier;

/**
 * The bounded stores the views read: one {@link Shelf} per stream, fed on the stream's thread
 * ({@link #live()} subscribed to the live stream, {@link #replay()} to the replay stream);
 * views pull from the stores once per frame. So a replayed robot's plot never mixes with the
 * live robot of the same number, and a seek can start the replay's stores afresh
 * ({@link #restartReplay}) without touching live data. The accessors return the stores the
 * views show: the replay's while {@code showReplay} says so (the console: while a replay is
 * open), else the live ones.
 */
public final class ViewStores {

    /** One set of stores: what the views read of one stream. */
    public record Shelf(TextLog text, PlotStore plots, LatestValues latest, NetworkLog network,
                        java.util.concurrent.atomic.AtomicReference<touchline.model.RosReadings> readings)
            implements EnvelopeSink {

        Shelf(int textLines, int plotPoints, int networkEnvelopes, long originMicros) {
            this(new TextLog(textLines), new PlotStore(plotPoints, originMicros), new LatestValues(),
                    new NetworkLog(networkEnvelopes),
                    new java.util.concurrent.atomic.AtomicReference<>(new touchline.model.RosReadings()));
        }

        /** Empties every store; versions and sequence numbers go on, so views notice. */
        void restart(long originMicros) {
            plots.restart(originMicros);
            latest.clear();
            text.forget();
            network.forget();
        }

        @Override
        public void accept(Envelope e) {
            if (!e.matchPart()) {
                network.accept(e); // the network log lists datagrams; a digest's parts are shown by the others
            }
            if (e.ros() != null && e.direction() == Direction.IN) {
                // a ROS 2 robot's log (/rosout) in the debug console, as the robot's text
                readings.get().log(e.kind(), e.ros()).ifPresent(l -> text.add(e, l));
                latest.acceptRos(e); // images, tables and markers for the views that show small robots' data
                return;
            }
            if (e.direction() != Direction.IN || !(e.message() instanceof Fumanoid.Message m)) {
                return; // the other stores keep only what robots sent
            }
            // the data found once for the three stores (each asked the message for its extension)
            Message own = DebugData.ownDataOf(e.kind(), m);
            text.add(e, own instanceof Fumanoid.DebugText t ? t : null);
            if (own instanceof Fumanoid.DebugPlot p) {
                plots.add(e.robotId(), p, e.timeMicros());
            }
            if (e.robotId() >= 0) {
                latest.accept(e, m, own);
            }
        }
    }

    private final Shelf live;
    private final Shelf replay;
    private final BooleanSupplier showReplay;

    public ViewStores(long originMicros) {
        this(TextLog.DEFAULT_CAPACITY, PlotStore.DEFAULT_POINTS, NetworkLog.DEFAULT_CAPACITY, originMicros, () -> false);
    }

    public ViewStores(int textLines, int plotPoints, int networkEnvelopes, long originMicros) {
        this(textLines, plotPoints, networkEnvelopes, originMicros, () -> false);
    }

    /** @param showReplay whether the views show the replay's stores rather than the live ones */
    public ViewStores(int textLines, int plotPoints, int networkEnvelopes, long originMicros,
                      BooleanSupplier showReplay) {
        this.live = new Shelf(textLines, plotPoints, networkEnvelopes, originMicros);
        this.replay = new Shelf(textLines, plotPoints, networkEnvelopes, originMicros);
        this.showReplay = showReplay;
    }

    /**
     * Empties the replay's stores (a replay opened, or it jumped): what the views show of it
     * from now on is as if it had been played from here. Plot times count from
     * {@code originMicros} (the recording's start). Live stores are untouched.
     */
    public void restartReplay(long originMicros) {
        replay.restart(originMicros);
    }

    /** What ROS 2 messages are read as beyond their types (the user's mapping file), live and replayed. */
    public void useRosMapping(touchline.model.RosMapping mapping) {
        live.readings().set(new touchline.model.RosReadings(mapping));
        replay.readings().set(new touchline.model.RosReadings(mapping));
    }

    /** The live stores, whatever the views show. */
    public Shelf live() { return live; }
    /** The replay's stores, whatever the views show. */
    public Shelf replay() { return replay; }

    /** Whether the views show the replay's stores (a replay is open) rather than the live ones. */
    public boolean showsReplay() {
        return showReplay.getAsBoolean();
    }

    private Shelf shown() {
        return showReplay.getAsBoolean() ? replay : live;
    }

    public TextLog text() { return shown().text(); }
    public PlotStore plots() { return shown().plots(); }
    public LatestValues latest() { return shown().latest(); }
    public NetworkLog network() { return shown().network(); }
}
