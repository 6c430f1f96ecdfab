package touchline.app;

import touchline.record.Player;
import touchline.record.PlayerState;
import touchline.record.PlaybackClock;
import touchline.record.Recording;
import touchline.record.TimelineEvent;
import touchline.transport.EnvelopeSink;

import java.util.List;
import java.util.Optional;

/**
 * A recording playing into the console's Envelope stream, so every view shows it as it showed
 * live traffic. A daemon thread pumps the player; the controls are the player's and may be
 * called from any thread (the UI's timeline calls them from the FX thread).
 */
public final class Replay implements AutoCloseable {

    private final Recording recording;
    private final Player player;
    private final Thread pump;
    private volatile boolean running = true;

    Replay(Recording recording, EnvelopeSink sink) {
        this.recording = recording;
        this.player = new Player(recording, sink, PlaybackClock.system());
        this.pump = new Thread(this::loop, "touchline-replay");
        pump.setDaemon(true);
        pump.start();
    }

    private void loop() {
        while (running) {
            long waitNanos;
            try {
                waitNanos = player.pump();
            } catch (RuntimeException e) {
                org.slf4j.LoggerFactory.getLogger(Replay.class).warn("replay stopped: {}", e.toString());
                return;
            }
            try {
                Thread.sleep(Math.max(1, Math.min(waitNanos > 0 ? waitNanos / 1_000_000 : 20, 20)));
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    public void play() { player.play(); }
    public void pause() { player.pause(); }
    public void seek(long timeMicros) { player.seek(timeMicros); }
    public Optional<TimelineEvent> seekToNext(TimelineEvent.Type type) { return player.seekToNext(type); }
    public double setSpeed(double factor) { return player.setSpeed(factor); }
    public void setLoop(long fromMicros, long toMicros) { player.setLoop(fromMicros, toMicros); }
    public void clearLoop() { player.clearLoop(); }
    public PlayerState state() { return player.snapshot(); }
    public List<TimelineEvent> events() { return player.events(); }
    /** What could not be read from the file (a cut-off end, a corrupt chunk, a schema that does not parse). */
    public List<String> problems() { return recording.problems(); }

    @Override
    public void close() {
        running = false;
        pump.interrupt();
        try {
            pump.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        player.close();
        recording.close();
    }
}
