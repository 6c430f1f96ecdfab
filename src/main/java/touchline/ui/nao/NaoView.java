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
import touchline.app.Naos;
import touchline.app.NaoFrame;
import touchline.app.NaoViewModel;
import touchline.protocol.nao.NaoModules;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.io.ByteArrayInputStream;
import java.util.Optional;

/**
 * The NAO tab: connect to a robot's RPC module and camera server, see the connection state,
 * browse modules and methods (discovered with {@code getMethodList}) and call one with typed
 * parameters, stand / sit / turn the head / say, walk with W A S D (Q E turn) while the view
 * has focus, and watch the camera. Everything it does and shows is its {@link NaoViewModel}'s
 * (in the application core, where a test reaches it): the view only binds its controls to it
 * and draws what it says on the frame pulse ({@link #refresh}) — the camera image is the
 * newest frame in the console's stream, so a remote Touchline's NAO and a replay are drawn too.
 */
public final class NaoView implements View {

    private final NaoViewModel model;
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

    private long shownMethods;
    private long shownFrame;

    public NaoView(ViewContext context, ViewSource source) {
        this(context.naos());
    }

    /** The view over {@code naos} (the window's, or a test's console's). */
    public NaoView(Naos naos) {
        this.model = new NaoViewModel(naos);
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
                connect.setSelected(model.connect(host.getText(), rpcPort.getText(), camPort.getText(),
                        keyDir.getText(), insecure.isSelected()));
            } else {
                model.disconnect();
            }
        });
        HBox top = new HBox(6, new Label("NAO"), host, new Label("RPC"), rpcPort, new Label("camera"), camPort,
                new Label("keys"), keyDir, insecure, connect, state);
        top.setPadding(new Insets(4));
        top.setAlignment(javafx.geometry.Pos.CENTER_LEFT);
        // a narrow pane scrolls the row rather than shrinking its labels and ports to "…"
        for (javafx.scene.Node n : top.getChildren()) {
            if (n instanceof javafx.scene.layout.Region r && n != keyDir && n != state) {
                r.setMinWidth(javafx.scene.layout.Region.USE_PREF_SIZE);
            }
        }

        module.getItems().setAll(NaoModules.ALL);
        module.setEditable(true);
        module.setValue("ALMotion");
        Button discover = new Button("Methods");
        discover.setId("nao-discover");
        discover.setOnAction(e -> model.discover(module.getValue()));
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
        stand.setId("nao-stand");
        stand.setOnAction(e -> model.stand());
        Button sit = new Button("Sit");
        sit.setOnAction(e -> model.sit());
        Button head = new Button("Turn head");
        head.setOnAction(e -> model.turnHead(headYaw.getValue()));
        Button say = new Button("Say");
        say.setOnAction(e -> model.say(sayText.getText()));
        Label walkHelp = new Label("Walk: click here, hold W/S forward/back, A/D sideways, Q/E turn");
        VBox controls = new VBox(4, new HBox(4, stand, sit), new HBox(4, head, headYaw), new HBox(4, say, sayText),
                walkHelp);
        controls.setPadding(new Insets(4));
        controls.setFocusTraversable(true);
        controls.setOnMouseClicked(e -> controls.requestFocus());
        controls.addEventHandler(KeyEvent.KEY_PRESSED, e -> walkKey(e, true));
        controls.addEventHandler(KeyEvent.KEY_RELEASED, e -> walkKey(e, false));
        controls.setId("nao-walk");

        resolution.getItems().setAll(0, 1, 2, 3);
        resolution.setValue(2);
        resolution.setOnAction(e -> model.setResolution(resolution.getValue()));
        cameraOn.setOnAction(e -> model.showCamera(cameraOn.isSelected()));
        cameraStats.setId("nao-camera-figures");
        image.setPreserveRatio(true);
        image.setFitWidth(480);
        VBox cam = new VBox(4, new HBox(4, cameraOn, new Label("resolution"), resolution, cameraStats), image);
        cam.setPadding(new Insets(4));

        root.setTop(top);
        root.setLeft(browser);
        root.setCenter(new VBox(controls, cam));
    }

    @Override
    public Node node() {
        return root;
    }

    private void callSelected() {
        model.call(module.getValue(), methods.getSelectionModel().getSelectedItem(), params.getText());
    }

    private void walkKey(KeyEvent e, boolean down) {
        String t = e.getCode().getChar();
        if (t.length() == 1 && model.walkKey(t.charAt(0), down)) {
            e.consume();
        }
    }

    @Override
    public void refresh(FrameContext frame) {
        state.setText(model.state());
        connect.setSelected(model.connected());
        if (!model.result().equals(result.getText())) {
            result.setText(model.result());
        }
        if (model.methodsVersion() != shownMethods) {
            shownMethods = model.methodsVersion();
            methods.getItems().setAll(model.methods());
        }
        Optional<NaoFrame> f = model.frame();
        if (f.isPresent() && f.get().sequence() != shownFrame) {
            shownFrame = f.get().sequence();
            image.setImage(new Image(new ByteArrayInputStream(f.get().jpeg())));
            frame.shown(f.get().timeMicros());
        } else if (f.isEmpty() && image.getImage() != null) {
            image.setImage(null); // a closed replay takes its frame with it
            shownFrame = 0;
        }
        cameraStats.setText(model.cameraFigures());
    }

    @Override
    public void close() {
        model.close();
    }
}
