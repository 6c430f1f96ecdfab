package touchline.app;

import touchline.transport.MicrosClock;
import touchline.transport.nao.NaoClientKeys;
import touchline.transport.nao.NaoLinkConfig;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * The NAOs driven through this console: sessions (RPC link and camera) and cameras alone, each
 * passing the console's gate and entering its stream, and the feeds the faces read of NAO
 * frames and calls (connected here, a remote Touchline's, replayed). Closing the console
 * disconnects them.
 */
public final class Naos {

    private final LiveField field;
    private final FieldGate gate;
    private final MicrosClock clock;
    private final SystemClock realClock;
    private final NaoCameraFeed camera;
    private final NaoCallFeed calls;
    private final List<NaoSession> sessions = new CopyOnWriteArrayList<>();
    private final List<NaoCamera> cameras = new CopyOnWriteArrayList<>();

    Naos(LiveField field, FieldGate gate, MicrosClock clock, SystemClock realClock, ReplaySlot replay) {
        this.field = field;
        this.gate = gate;
        this.clock = clock;
        this.realClock = realClock;
        this.camera = new NaoCameraFeed(clock, field.replayClock(), replay::open);
        this.calls = new NaoCallFeed(replay::open);
        if (field.withModel()) {
            field.bus().subscribe(camera.live());
            field.replayStream().subscribe(camera.replay());
            field.bus().subscribe(calls.live());
            field.replayStream().subscribe(calls.replay());
        }
    }

    /**
     * Connects to a NAO ({@code rpcPort}, and its camera at {@code camPort} unless 0): every call
     * and move of the session passes this console's gate (match mode, a remote view) and its
     * traffic enters this console's stream. Several NAOs may be connected at once; closing a
     * session disconnects it.
     *
     * @param keys CURVE client keys, or null: insecure
     */
    public NaoSession connect(String host, int rpcPort, int camPort, NaoClientKeys keys, NaoLinkConfig naoConfig) {
        NaoSession session = new NaoSession(host, rpcPort, camPort, naoConfig, keys, field.live(), gate.forNao(), clock,
                realClock, sessions::remove);
        sessions.add(session);
        return session.start();
    }

    /**
     * Opens a NAO's camera server alone (no RPC link), its frames entering this console's stream
     * ({@link #camera()}); fetching frames sends no command, so match mode does not hold it.
     * Closing it (or the console) stops it.
     *
     * @param keys CURVE client keys, or null: insecure
     */
    public NaoCamera connectCamera(String host, int camPort, NaoClientKeys keys) {
        NaoCamera c = new NaoCamera(host, camPort, field.live(), keys, clock, realClock, cameras::remove);
        cameras.add(c);
        return c.start();
    }

    /**
     * The NAO cameras' newest frame and rates as this console's stream carries them: frames of
     * the NAOs connected here, of a remote Touchline's NAO when viewing one, and of a replay.
     */
    public NaoCameraFeed camera() {
        return camera;
    }

    /** The NAO calls' newest outcome in words as this console's stream carries them (here, a remote Touchline's, replayed). */
    public NaoCallFeed calls() {
        return calls;
    }

    /** The NAOs connected through this console, oldest first. */
    public List<NaoSession> sessions() {
        return List.copyOf(sessions);
    }

    /** True once the console views a remote Touchline: NAO commands are off ({@link RemoteView#COMMANDS_OFF}). */
    public boolean commandsOff() {
        return gate.commandsOff();
    }

    void restartReplay() {
        camera.restartReplay();
        calls.restartReplay();
    }

    /** Closes every NAO link and camera, and waits (at most 3 s) for their threads' last envelopes. */
    void close() {
        List<java.util.concurrent.CompletableFuture<Void>> threads = new java.util.ArrayList<>();
        for (NaoSession nao : sessions) {
            nao.close();
            threads.add(nao.stopped());
        }
        for (NaoCamera c : cameras) {
            c.close();
            threads.add(c.stopped().toCompletableFuture());
        }
        try { // their last envelopes (calls ended as lost) reach the recording, closed after this
            java.util.concurrent.CompletableFuture.allOf(threads.toArray(java.util.concurrent.CompletableFuture[]::new))
                    .get(3, java.util.concurrent.TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
            org.slf4j.LoggerFactory.getLogger(Naos.class).warn("NAO links still stopping: {}", e.toString());
        }
    }
}
