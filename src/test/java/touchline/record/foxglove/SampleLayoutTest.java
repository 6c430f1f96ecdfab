package touchline.record.foxglove;

import org.json.JSONArray;
import org.json.JSONObject;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.proto.Fumanoid;
import touchline.protocol.MessageKinds;
import touchline.record.ChunkCompression;
import touchline.record.EnvelopeWriter;
import touchline.record.McapReader;
import touchline.record.Recording;
import touchline.transport.Envelope;

import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * samples/lichtblick/demo-team-layout.json names only topics an export of the demo team's
 * kinds of data has (so no panel of it stays empty for a wrong name), and every panel in its
 * arrangement is configured.
 */
class SampleLayoutTest {

    private static final Path LAYOUT = Path.of("samples/lichtblick/demo-team-layout.json");

    @TempDir
    Path dir;

    @Test
    void everyTopicTheLayoutNamesIsInAnExportOfTheDemoTeam() throws Exception {
        JSONObject layout = new JSONObject(Files.readString(LAYOUT));
        Set<String> named = new TreeSet<>();
        collect(layout.getJSONObject("configById"), named);

        List<Envelope> sent = new ArrayList<>();
        long t = 1_760_000_000_000_000L;
        for (int robot = 1; robot <= 3; robot++) {
            sent.add(FoxgloveFixture.status(t++, robot, 100, 200, 0));
            sent.add(FoxgloveFixture.text(t++, robot, "demo.text", "hi"));
            sent.add(FoxgloveFixture.image(t++, robot, Fumanoid.ImageFormat.GRAY8, 4, 3, new byte[12]));
            sent.add(FoxgloveFixture.regions(t++, robot, new int[]{1, 1, 1, 5, 5}));
            sent.add(FoxgloveFixture.in(t++, robot, "debugPlot", Fumanoid.Message.newBuilder().setRobotID(robot)
                    .setExtension(Fumanoid.debugPlot, Fumanoid.DebugPlot.newBuilder().setOption("demo.plotter")
                            .addSamples(Fumanoid.PlotSample.newBuilder().setSeries("vx").setValue(1))
                            .addSamples(Fumanoid.PlotSample.newBuilder().setSeries("vy").setValue(2)).build()).build()));
            sent.add(FoxgloveFixture.in(t++, robot, "relativePositions", Fumanoid.Message.newBuilder().setRobotID(robot)
                    .setExtension(Fumanoid.relativePositions, Fumanoid.RelativePositions.newBuilder().setOption("demo.relative")
                            .addObjects(Fumanoid.RelativeObject.newBuilder().setLabel("ball").setX(500)).build()).build()));
        }
        Path export = FoxgloveFixture.recordAndExport(dir, sent);
        Set<String> topics;
        try (McapReader m = McapReader.open(export)) {
            topics = m.channels().values().stream().map(McapReader.ChannelInfo::topic).collect(Collectors.toSet());
        }
        named.removeAll(topics);
        assertTrue(named.isEmpty(), "the layout names topics the export does not have: " + named + "; it has " + topics);
    }

    @Test
    void everyPanelInTheArrangementIsConfigured() throws Exception {
        JSONObject layout = new JSONObject(Files.readString(LAYOUT));
        Set<String> panels = new TreeSet<>();
        arranged(layout.get("layout"), panels);
        assertTrue(layout.getJSONObject("configById").keySet().containsAll(panels), panels.toString());
        assertTrue(panels.containsAll(Set.of("3D!field", "Plot!robots", "Image!regions", "RosOut!robot1")), panels.toString());
    }

    /**
     * The shape Lichtblick reads (checked against its sources, packages/suite-base: LayoutData,
     * panels' config types; Lichtblick itself cannot run here): panel ids {@code Type!name} of
     * its panel types, a Plot's required settings with values it knows, titles under its own
     * key, image annotations as topic → settings, Log settings, and the layout's top-level keys.
     */
    @Test
    void itHasTheShapeLichtblickReads() throws Exception {
        JSONObject layout = new JSONObject(Files.readString(LAYOUT));
        assertTrue(layout.keySet().containsAll(Set.of("configById", "globalVariables", "userNodes", "layout")),
                layout.keySet().toString());
        JSONObject configs = layout.getJSONObject("configById");
        for (String id : configs.keySet()) {
            String type = id.substring(0, id.indexOf('!'));
            JSONObject c = configs.getJSONObject(id);
            assertTrue(Set.of("3D", "Plot", "Image", "RosOut").contains(type), "a Lichtblick panel type: " + id);
            assertTrue(!c.has("title"), id + ": Lichtblick takes a panel's title from lichtblickPanelTitle");
            switch (type) {
                case "Plot" -> {
                    for (String key : List.of("paths", "showLegend", "legendDisplay", "showPlotValuesInLegend",
                            "showXAxisLabels", "showYAxisLabels", "isSynced", "xAxisVal", "sidebarDimension")) {
                        assertTrue(c.has(key), id + " has " + key);
                    }
                    assertTrue(Set.of("floating", "top", "left", "none").contains(c.getString("legendDisplay")), id);
                    assertTrue(Set.of("timestamp", "index", "custom", "currentCustom").contains(c.getString("xAxisVal")), id);
                    for (Object p : c.getJSONArray("paths")) {
                        JSONObject path = (JSONObject) p;
                        assertTrue(path.get("enabled") instanceof Boolean, id);
                        assertTrue(Set.of("receiveTime", "headerStamp").contains(path.getString("timestampMethod")), id);
                    }
                }
                case "Image", "3D" -> {
                    JSONObject image = c.getJSONObject("imageMode");
                    if (image.has("annotations")) {
                        JSONObject annotations = image.getJSONObject("annotations");
                        annotations.keySet().forEach(t -> assertTrue(
                                annotations.getJSONObject(t).get("visible") instanceof Boolean, id + " " + t));
                    }
                    assertTrue(c.getJSONObject("topics") != null && c.getJSONObject("layers") != null, id);
                }
                case "RosOut" -> {
                    assertTrue(c.get("searchTerms") instanceof JSONArray, id);
                    // foxglove.Log levels: 1 DEBUG … 5 FATAL; the served debug text is INFO (2)
                    assertTrue(c.getInt("minLogLevel") >= 1 && c.getInt("minLogLevel") <= 2, id);
                    assertTrue(c.getString("topicToRender").matches("/robot/\\d+/log"), id);
                }
                default -> { }
            }
        }
    }

    private static void arranged(Object node, Set<String> out) {
        if (node instanceof String id) {
            out.add(id);
        } else if (node instanceof JSONObject split) {
            arranged(split.get("first"), out);
            arranged(split.get("second"), out);
        }
    }

    /** Topics in panel settings: Log and Image topics, annotation and 3D topic keys, and the topic of each plot path. */
    private static void collect(Object node, Set<String> out) {
        if (node instanceof JSONObject o) {
            for (String key : o.keySet()) {
                Object v = o.get(key);
                if ((key.equals("topicToRender") || key.equals("imageTopic")) && v instanceof String s) {
                    out.add(s);
                } else if ((key.equals("topics") || key.equals("annotations")) && v instanceof JSONObject keys) {
                    out.addAll(keys.keySet());
                } else if (key.equals("value") && v instanceof String path && path.startsWith("/")) {
                    out.add(path.substring(0, path.indexOf('.', path.lastIndexOf('/'))));
                } else {
                    collect(v, out);
                }
            }
        } else if (node instanceof JSONArray a) {
            a.forEach(x -> collect(x, out));
        }
    }
}
