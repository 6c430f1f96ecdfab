package touchline.ui.nao;

import javafx.geometry.Insets;
import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.ListView;
import javafx.scene.control.Slider;
import javafx.scene.control.TextField;
import javafx.scene.control.ToggleButton;
import javafx.scene.image.Image;
import javafx.scene.image.ImageView;
import javafx.scene.input.KeyEvent;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.VBox;
import touchline.protocol.nao.ParamSyntax;
import touchline.transport.EnvelopeSink;
import touchline.transport.nao.CallOutcome;
import touchline.transport.nao.CameraFrame;
import touchline.transport.nao.CameraSettings;
import touchline.transport.nao.NaoCall;
import touchline.transport.nao.NaoCameraStream;
import touchline.transport.nao.NaoEnvelopeChannel;
import touchline.transport.nao.NaoLink;
import touchline.transport.nao.NaoLinkConfig;
import touchline.transport.nao.NaoMoves;
import touchline.transport.nao.WalkInput;
import touchline.ui.FrameContext;
import touchline.ui.View;
import touchline.ui.ViewContext;
import touchline.ui.ViewSource;

import java.io.ByteArrayInputStream;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;

/**
 * The NAO tab: connect to a robot's RPC module and camera server, see the connection state,
 * browse modules and methods (discovered with {@code getMethodList}) and call one with typed
 * parameters, stand / sit / turn the head / say, walk with W A S D (Q E turn) while the view
 * has focus, and watch the camera. Network results land in volatile fields and are shown by
 * {@link #refresh} on the frame pulse; the view talks only to {@link NaoLink} and
 * {@link NaoCameraStream}, never to sockets.
 */
public final class NaoView implements View {

    static final List<String> MODULES = List.of("ALMotion", "ALRobotPosture", "ALTextToSpeech", "ALMemory",
            "ALBattery", "ALVideoDevice", "Robot");

    private final EnvelopeSink sink;
    private final BorderPane root = new BorderPane();
    private final TextField host = new TextField("127.0.0.1");
    private final TextField rpcPort = new TextField("5555");
    private final TextField camPort = new TextField("5556");
    private final ToggleButton connect = new ToggleButton("Connect");
    private final Label state = new Label("not connected");
    private final TextField keyDir = new TextField(
            touchline.security.KeyDir.locate(java.util.Optional.empty(), System.getenv()).path().toString());
    private final javafx.scene.control.CheckBox insecure = new javafx.scene.control.CheckBox("insecure (old robot)");
    private final ComboBox<String> module = new ComboBox<>();
    private final ListView<String> methods = new ListView<>();
    private final TextField params = new TextField();
    private final Label result = new Label();
    private final TextField sayText = new TextField("Hello");
    private final Slider headYaw = new Slider(-2.0857, 2.0857, 0);
    private final ToggleButton cameraOn = new ToggleButton("Camera");
    private final ComboBox<Integer> resolution = new ComboBox<>();
    private final ImageView image = new ImageView();
    private final Label cameraStats = new Label();
    private final Set<Character> heldKeys = new HashSet<>();

    private NaoEnvelopeChannel channel;
    private NaoLink link;
    private NaoMoves moves;
    private NaoCameraStream camera;
    private AutoCloseable viewer;
    private volatile String lastResult = "";
    private volatile List<String> discovered;
    private long shownFrame;
    private touchline.app.game.MatchMode matchMode;

    public NaoView(ViewContext context, ViewSource source) {
        this(context.console().bus());
        this.matchMode = context.console().matchMode();
    }

    /** For tests and embedding: envelopes go to {@code sink}. */
    public NaoView(EnvelopeSink sink) {
        this.sink = sink;
        host.setPrefColumnCount(10);
        rpcPort.setPrefColumnCount(5);
        camPort.setPrefColumnCount(5);
        connect.setId("nao-connect");
        host.setId("nao-host");
        rpcPort.setId("nao-rpc-port");
        camPort.setId("nao-cam-port");
        module.setId("nao-module");
        methods.setId("nao-methods");
        params.setId("nao-params");
        cameraOn.setId("nao-camera");
        image.setId("nao-image");
        state.setId("nao-state");
        keyDir.setId("nao-keys");
        keyDir.setPrefColumnCount(14);
        keyDir.setTooltip(new javafx.scene.control.Tooltip("key directory: console.secret and nao-server.public "
                + "(docs/security.md)"));
        insecure.setId("nao-insecure");
        connect.setOnAction(e -> {
            if (connect.isSelected()) {
                open();
            } else {
                shut();
            }
        });
        HBox top = new HBox(6, new Label("NAO"), host, new Label("RPC"), rpcPort, new Label("camera"), camPort,
                new Label("keys"), keyDir, insecure, connect, state);
        top.setPadding(new Insets(4));

        module.getItems().setAll(MODULES);
        module.setEditable(true);
        module.setValue("ALMotion");
        Button discover = new Button("Methods");
        discover.setId("nao-discover");
        discover.setOnAction(e -> call(NaoCall.of(module.getValue(), "getMethodList"), true));
        params.setPromptText("parameters, e.g. HeadYaw, 0.5, 0.2  or  [HeadYaw, HeadPitch], [0.1, 0.2], 0.3");
        Button call = new Button("Call");
        call.setId("nao-call");
        call.setOnAction(e -> callSelected());
        methods.setOnMouseClicked(e -> {
            if (e.getClickCount() == 2) {
                callSelected();
            }
        });
        result.setId("nao-result");
        result.setWrapText(true);
        VBox browser = new VBox(4, new HBox(4, module, discover), methods, params, call, result);
        browser.setPadding(new Insets(4));
        browser.setPrefWidth(320);

        Button stand = new Button("Stand");
        stand.setOnAction(e -> sequence(moves == null ? null : moves.stand()));
        Button sit = new Button("Sit");
        sit.setOnAction(e -> sequence(moves == null ? null : moves.sit()));
        Button head = new Button("Turn head");
        head.setOnAction(e -> sequence(moves == null ? null : moves.turnHead(headYaw.getValue())));
        Button say = new Button("Say");
        say.setOnAction(e -> outcome(moves == null ? null : moves.say(sayText.getText())));
        Label walkHelp = new Label("Walk: click here, hold W/S forward/back, A/D sideways, Q/E turn");
        VBox controls = new VBox(4, new HBox(4, stand, sit), new HBox(4, head, headYaw), new HBox(4, say, sayText),
                walkHelp);
        controls.setPadding(new Insets(4));
        controls.setFocusTraversable(true);
        controls.setOnMouseClicked(e -> controls.requestFocus());
        controls.addEventHandler(KeyEvent.KEY_PRESSED, e -> walkKey(e, true));
        controls.addEventHandler(KeyEvent.KEY_RELEASED, e -> walkKey(e, false));

        resolution.getItems().setAll(0, 1, 2, 3);
        resolution.setValue(2);
        resolution.setOnAction(e -> configureCamera());
        cameraOn.setOnAction(e -> toggleCamera());
        image.setPreserveRatio(true);
        image.setFitWidth(480);
        VBox cam = new VBox(4, new HBox(4, cameraOn, new Label("resolution"), resolution, cameraStats), image);
        cam.setPadding(new Insets(4));

        root.setTop(top);
        root.setLeft(browser);
        root.setCenter(new VBox(controls, cam));
    }

    private void open() {
        try {
            String h = host.getText().strip();
            int rpc = Integer.parseInt(rpcPort.getText().strip());
            int cam = Integer.parseInt(camPort.getText().strip());
            touchline.transport.nao.NaoClientKeys keys;
            try {
                keys = insecure.isSelected() ? null
                        : touchline.transport.nao.NaoClientKeys.load(
                                new touchline.security.KeyDir(java.nio.file.Path.of(keyDir.getText().strip())));
            } catch (touchline.security.KeyException e) {
                lastResult = e.getMessage() + ". For an old robot side without keys: tick 'insecure'";
                connect.setSelected(false);
                return;
            }
            channel = new NaoEnvelopeChannel(sink);
            link = new NaoLink(h, rpc, NaoLinkConfig.defaults(), channel, keys);
            if (matchMode != null) {
                touchline.app.game.MatchMode mm = matchMode;
                link.setSendGate(() -> !mm.hold("NAO command"), mm::notice); // no commands to a robot during play
            }
            moves = new NaoMoves(link);
            camera = new NaoCameraStream(h, cam, channel, keys);
            configureCamera();
            toggleCamera();
        } catch (NumberFormatException e) {
            lastResult = "bad port: " + e.getMessage();
            connect.setSelected(false);
        }
    }

    private void shut() {
        closeViewer();
        if (camera != null) {
            camera.close();
        }
        if (link != null) {
            link.close();
        }
        if (channel != null) {
            channel.close();
        }
        camera = null;
        link = null;
        moves = null;
        channel = null;
    }

    private void callSelected() {
        String method = methods.getSelectionModel().getSelectedItem();
        if (method == null) {
            lastResult = "choose a method (\"Methods\" lists them)";
            return;
        }
        try {
            String text = params.getText().strip();
            Object parsed = text.isEmpty() ? List.of() : ParamSyntax.parse("[" + text + "]");
            call(new NaoCall(module.getValue(), method, (List<Object>) parsed), false);
        } catch (IllegalArgumentException e) {
            lastResult = e.getMessage();
        }
    }

    private void call(NaoCall call, boolean discovery) {
        if (link == null) {
            lastResult = "not connected";
            return;
        }
        link.call(call).thenAccept(outcome -> {
            lastResult = call.qualifiedName() + ": " + outcome.describe();
            if (discovery && outcome instanceof CallOutcome.Value v && v.value() instanceof List<?> names) {
                discovered = names.stream().map(String::valueOf).sorted().toList();
            }
        });
    }

    private void sequence(CompletableFuture<touchline.transport.nao.SequenceOutcome> f) {
        if (f == null) {
            lastResult = "not connected";
            return;
        }
        f.thenAccept(o -> lastResult = o.describe());
    }

    private void outcome(CompletableFuture<CallOutcome> f) {
        if (f == null) {
            lastResult = "not connected";
            return;
        }
        f.thenAccept(o -> lastResult = o.describe());
    }

    private void walkKey(KeyEvent e, boolean down) {
        String t = e.getCode().getChar();
        if (t.length() != 1 || "WASDQE".indexOf(t.charAt(0)) < 0 || moves == null) {
            return;
        }
        boolean changed = down ? heldKeys.add(t.charAt(0)) : heldKeys.remove(t.charAt(0));
        if (changed) {
            moves.walk(WalkInput.fromKeys(heldKeys, 0.6f)).thenAccept(o -> {
                if (!o.ok() && !(o instanceof CallOutcome.Superseded)) {
                    lastResult = "walk: " + o.describe();
                }
            });
        }
        e.consume();
    }

    private void configureCamera() {
        if (camera != null) {
            CameraSettings s = camera.settings();
            camera.configure(new CameraSettings(resolution.getValue(), s.colorSpace(), s.fps()));
        }
    }

    private void toggleCamera() {
        closeViewer();
        if (camera != null && cameraOn.isSelected()) {
            viewer = camera.subscribe();
        }
    }

    private void closeViewer() {
        if (viewer != null) {
            try {
                viewer.close();
            } catch (Exception ignored) {
                // a subscription handle's close does not fail
            }
            viewer = null;
        }
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        NaoLink l = link;
        state.setText(l == null ? "not connected" : l.state().name().toLowerCase() + (l.secure() ? " (encrypted)"
                : " (INSECURE)") + "  " + l.stats().sent() + " sent, " + l.stats().replies() + " replies, "
                + l.stats().timeouts() + " timeouts" + (l.securityProblem().isEmpty() ? "" : " — " + l.securityProblem()));
        if (!lastResult.equals(result.getText())) {
            result.setText(lastResult);
        }
        List<String> d = discovered;
        if (d != null) {
            discovered = null;
            methods.getItems().setAll(d);
        }
        NaoCameraStream c = camera;
        if (c != null) {
            CameraFrame f = c.latestFrame();
            if (f != null && f.sequence() != shownFrame) {
                shownFrame = f.sequence();
                image.setImage(new Image(new ByteArrayInputStream(f.jpeg())));
                frame.shown(f.receiveTimeMicros());
            }
            String err = c.lastError();
            cameraStats.setText(String.format("%.1f fps, %.0f B/frame%s", c.measuredFps(), c.bytesPerFrame(),
                    err == null ? "" : "  " + err));
        }
    }

    @Override
    public void close() {
        shut();
    }
}
