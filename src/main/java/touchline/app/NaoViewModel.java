package touchline.app;

import touchline.protocol.nao.ParamSyntax;
import touchline.security.KeyDir;
import touchline.security.KeyException;
import touchline.transport.nao.CallOutcome;
import touchline.transport.nao.CameraSettings;
import touchline.transport.nao.NaoCall;
import touchline.transport.nao.NaoClientKeys;
import touchline.transport.nao.NaoLinkConfig;
import touchline.transport.nao.SequenceOutcome;
import touchline.transport.nao.WalkInput;

import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CompletableFuture;

/**
 * What the window's NAO view shows and does, without JavaFX: the view binds its fields and
 * buttons to this and draws what it says once per frame. It connects through the core
 * ({@link Naos#connect}), so every call and move passes the console's gate; it parses
 * the typed parameters ({@link ParamSyntax}); it keeps the held walk keys, the newest
 * outcome in words ({@link #result()}), the discovered methods and the camera's wishes.
 * The camera frame it offers ({@link #frame()}) is the console's stream's newest, so the same
 * view draws a NAO connected here, a remote Touchline's NAO and a replay. On a console that
 * views a remote Touchline every command is refused with {@link RemoteView#COMMANDS_OFF}, as the
 * other views' commands are. Results arrive on the link's threads and are read by the view on
 * its own: they are volatile.
 */
public final class NaoViewModel implements AutoCloseable {

    /** How fast W A S D Q E walk: the share of the NAO's top speed. */
    static final float WALK_SPEED = 0.6f;
    static final String NOT_CONNECTED = "not connected";

    private final Naos naos;
    private final Set<Character> heldKeys = new HashSet<>(); // guarded by itself
    private volatile NaoSession session;
    private volatile String result = "";
    /** The stream's call line's version when this view told its own {@link #result} last. */
    private volatile long toldAt;
    private volatile List<String> methods = List.of();
    private final java.util.concurrent.atomic.AtomicLong methodsVersion = new java.util.concurrent.atomic.AtomicLong();
    private volatile boolean cameraWanted;
    private volatile int resolution = CameraSettings.DEFAULT.resolution();

    public NaoViewModel(Naos naos) {
        this.naos = naos;
    }

    // ---------------------------------------------------------------- connection

    /**
     * Connects to the NAO at {@code host} with the ports and keys as typed: CURVE keys from
     * {@code keyDir} unless {@code insecure}, the camera unless its port is 0. False (and
     * {@link #result()} says why) for a bad port, unusable keys, or on a console viewing a
     * remote Touchline.
     */
    public boolean connect(String host, String rpcPort, String camPort, String keyDir, boolean insecure) {
        if (naos.commandsOff()) {
            tell(RemoteView.COMMANDS_OFF);
            return false;
        }
        int rpc;
        int cam;
        try {
            rpc = Integer.parseInt(rpcPort.strip());
            cam = Integer.parseInt(camPort.strip());
        } catch (NumberFormatException e) {
            tell("bad port: " + e.getMessage());
            return false;
        }
        NaoClientKeys keys;
        try {
            keys = insecure ? null : NaoClientKeys.load(new KeyDir(Path.of(keyDir.strip())));
        } catch (KeyException e) {
            tell(e.getMessage() + ". For an old robot side without keys: tick 'insecure'");
            return false;
        }
        disconnect();
        NaoSession s = naos.connect(host.strip(), rpc, cam, keys, NaoLinkConfig.defaults());
        s.camera().ifPresent(c -> {
            CameraSettings was = c.settings();
            c.configure(new CameraSettings(resolution, was.colorSpace(), was.fps()));
            c.watch(cameraWanted);
        });
        session = s;
        return true;
    }

    public void disconnect() {
        NaoSession s = session;
        session = null;
        if (s != null) {
            s.close();
        }
    }

    public boolean connected() {
        return session != null;
    }

    /** The link in words ("online (encrypted)  3 sent, ..."), or why there is none. */
    public String state() {
        NaoSession s = session;
        if (s != null) {
            return s.describe();
        }
        return naos.commandsOff() ? "viewing a remote Touchline: its NAO's camera is shown here" : NOT_CONNECTED;
    }

    // ---------------------------------------------------------------- calls and moves

    /**
     * The newest outcome in words: a call's value or error, a move's, a parameter that did not
     * parse. On a console viewing a remote Touchline, or replaying, the NAO calls in the stream
     * count too ({@link NaoCallFeed}): the newer of theirs and this view's own is shown.
     */
    public String result() {
        NaoCallFeed calls = naos.calls();
        if (naos.commandsOff() || calls.showsReplay()) {
            String line = calls.line();
            if (calls.version() > toldAt && !line.isEmpty()) {
                return line;
            }
        }
        return result;
    }

    /** The methods the last {@link #discover} found, sorted; {@link #methodsVersion()} changes with them. */
    public List<String> methods() {
        return methods;
    }

    public long methodsVersion() {
        return methodsVersion.get();
    }

    /** Asks {@code module} for its methods ({@code getMethodList}). */
    public void discover(String module) {
        NaoCall call = NaoCall.of(module, "getMethodList");
        session().ifPresent(s -> s.call(call).thenAccept(outcome -> {
            tell(call.qualifiedName() + ": " + outcome.describe());
            if (outcome instanceof CallOutcome.Value v && v.value() instanceof List<?> names) {
                methods = names.stream().map(String::valueOf).sorted().toList();
                methodsVersion.incrementAndGet();
            }
        }));
    }

    /**
     * Calls {@code module.method} with the parameters as typed, comma-separated ({@link
     * ParamSyntax}: {@code HeadYaw, 0.5} or {@code [HeadYaw, HeadPitch], [0.1, 0.2], 0.3}).
     */
    public void call(String module, String method, String params) {
        if (naos.commandsOff()) {
            tell(RemoteView.COMMANDS_OFF);
            return;
        }
        if (method == null) {
            tell("choose a method (\"Methods\" lists them)");
            return;
        }
        NaoCall call;
        try {
            call = new NaoCall(module, method, parse(params));
        } catch (IllegalArgumentException e) {
            tell(e.getMessage());
            return;
        }
        Optional<NaoSession> s = session();
        if (s.isEmpty()) {
            return;
        }
        s.get().call(call).thenAccept(outcome -> tell(call.qualifiedName() + ": " + outcome.describe()));
    }

    public void stand() {
        session().ifPresent(s -> said(s.stand()));
    }

    public void sit() {
        session().ifPresent(s -> said(s.sit()));
    }

    public void turnHead(double yawRadians) {
        session().ifPresent(s -> said(s.turnHead(yawRadians)));
    }

    public void say(String text) {
        session().ifPresent(s -> s.say(text).thenAccept(o -> tell(o.describe())));
    }

    /**
     * A walk key (W S A D Q E, upper-case) went down or up: the NAO walks as the held keys say.
     * False for any other key (the view lets it go on).
     */
    public boolean walkKey(char key, boolean down) {
        if ("WASDQE".indexOf(key) < 0) {
            return false;
        }
        Optional<String> no = refused();
        if (no.isPresent()) {
            tell("walk: " + no.get());
            return true;
        }
        NaoSession s = session;
        WalkInput input;
        synchronized (heldKeys) {
            boolean changed = down ? heldKeys.add(key) : heldKeys.remove(key);
            if (!changed || s == null) {
                return true;
            }
            input = WalkInput.fromKeys(heldKeys, WALK_SPEED);
        }
        s.walk(input).thenAccept(o -> {
            if (!o.ok() && !(o instanceof CallOutcome.Superseded)) {
                tell("walk: " + o.describe());
            }
        });
        return true;
    }

    // ---------------------------------------------------------------- camera

    /** Fetch frames ({@code true}) or not, from the NAO connected here. */
    public void showCamera(boolean on) {
        cameraWanted = on;
        camera().ifPresent(c -> c.watch(on));
    }

    /** The resolution id to ask for (0 160x120 .. 3 1280x960); an unknown one is refused (IllegalArgumentException). */
    public void setResolution(int id) {
        camera().ifPresent(c -> c.configure(new CameraSettings(id, c.settings().colorSpace(), c.settings().fps())));
        resolution = id;
    }

    /** The newest camera frame in the console's stream: fetched here, a remote Touchline's, or replayed. */
    public Optional<NaoFrame> frame() {
        return naos.camera().latest();
    }

    /** "14.8 fps, 23011 B/frame", and what is wrong with the camera if something is. */
    public String cameraFigures() {
        NaoCameraFeed feed = naos.camera();
        String problem = camera().map(NaoCamera::problem).filter(p -> !p.isEmpty()).orElse(feed.problem());
        return String.format(java.util.Locale.ROOT, "%.1f fps, %.0f B/frame%s", feed.framesPerSecond(),
                feed.bytesPerFrame(), problem.isEmpty() ? "" : "  " + problem);
    }

    @Override
    public void close() {
        disconnect();
    }

    // ---------------------------------------------------------------- helpers

    private Optional<NaoCamera> camera() {
        NaoSession s = session;
        return s == null ? Optional.empty() : s.camera();
    }

    /** Why no command goes out from here: a remote view, or no NAO connected. */
    private Optional<String> refused() {
        if (naos.commandsOff()) {
            return Optional.of(RemoteView.COMMANDS_OFF);
        }
        return session == null ? Optional.of(NOT_CONNECTED) : Optional.empty();
    }

    /** The session to command, or empty after saying why there is none. */
    private Optional<NaoSession> session() {
        Optional<String> no = refused();
        no.ifPresent(this::tell);
        return no.isPresent() ? Optional.empty() : Optional.ofNullable(session);
    }

    private void said(CompletableFuture<SequenceOutcome> moves) {
        moves.thenAccept(o -> tell(o.describe()));
    }

    /** This view's own outcome becomes the newest. */
    private void tell(String what) {
        toldAt = naos.calls().version();
        result = what;
    }

    @SuppressWarnings("unchecked")
    private static List<Object> parse(String params) {
        String text = params == null ? "" : params.strip();
        return text.isEmpty() ? List.of() : (List<Object>) ParamSyntax.parse("[" + text + "]");
    }
}
