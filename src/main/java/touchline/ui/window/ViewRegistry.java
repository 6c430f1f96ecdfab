package touchline.ui.window;

import touchline.proto.Fumanoid.DebugKind;
import touchline.ui.replay.ReplayView;
import touchline.ui.consoles.DebugConsoleView;
import touchline.ui.field.FieldView;
import touchline.ui.plots.ImageDataView;
import touchline.ui.consoles.NetworkView;
import touchline.ui.options.OptionsView;
import touchline.ui.plots.PlotView;
import touchline.ui.consoles.RawDataView;
import touchline.ui.field.RegionOverlayView;
import touchline.ui.field.RelativePositionsView;
import touchline.ui.robots.RobotsView;
import touchline.ui.consoles.TableDataView;
import touchline.ui.consoles.TextView;

import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * Every view the console offers, in one list: an entry here is all it takes for a view to
 * appear in the View menu, in quick-open, in the help and in saved layouts, and (through its
 * kinds) to open on double-click of a debug option.
 */
public final class ViewRegistry {

    public static final String RAW = "raw";

    private final List<ViewSpec> specs = List.of(
            new ViewSpec("robots", "Robots", "Every robot seen: ID, name, team, battery, role, state, online/offline, "
                    + "traffic and malformed packets; bad sources and notes below.", Set.of(),
                    (c, s) -> new RobotsView(c)),
            new ViewSpec("options", "Debug options", "Per robot the debug options it offers. Type to filter, Space "
                    + "toggles, double-click opens the visualisation.", Set.of(), (c, s) -> new OptionsView(c)),
            new ViewSpec("debug-console", "Debug console", "Time-stamped text from the robots; filter by robot, "
                    + "search, pause, copy.", Set.of(), (c, s) -> new DebugConsoleView(c)),
            new ViewSpec("network", "Network console", "Every datagram in and out with protobuf text and hex; "
                    + "filter by robot, direction, kind.", Set.of(), (c, s) -> new NetworkView(c)),
            new ViewSpec("field", "Field", "The field from above with every robot's reported position and role, "
                    + "plus field objects of a chosen option.", Set.of(DebugKind.FIELD_VALUE), FieldView::new),
            new ViewSpec("regions", "Region overlay", "HaViMo2 frame (blue), region-growing rectangles (red, filled in "
                    + "their colour class) and the grid, with a legend.",
                    Set.of(DebugKind.REGION_GROWING_VALUE, DebugKind.GRID_VALUE), RegionOverlayView::new),
            new ViewSpec("plot", "Plot", "Line plot of an option's series (NaN skipped and counted, bursts decimated).",
                    Set.of(DebugKind.PLOT_VALUE), PlotView::new),
            new ViewSpec("field-plot", "Plot fields", "Plot any numeric field of any message kind (the teams' own "
                    + "types too) by its field path, several robots in one plot with a legend; Export CSV… writes the "
                    + "plotted data. Type to filter the paths, Enter adds one.", Set.of(),
                    (c, s) -> new touchline.ui.plots.FieldPlotView(c)),
            new ViewSpec("table", "Table", "An option's table as the robot sends it.",
                    Set.of(DebugKind.TABLE_VALUE), TableDataView::new),
            new ViewSpec("relative", "Relative positions", "Objects around the robot, robot-centred (x forward); a ROS 2 robot's "
                    + "markers and the other robots in its own frame (base_link, or one chosen).",
                    Set.of(DebugKind.RELATIVE_POSITIONS_VALUE), RelativePositionsView::new),
            new ViewSpec("image", "Image", "An option's image (GRAY8, RGB888, colour classes, JPEG, PNG); images "
                    + "that do not decode are marked.", Set.of(DebugKind.IMAGE_VALUE), ImageDataView::new),
            new ViewSpec("text", "Text", "An option's text lines.", Set.of(DebugKind.TEXT_VALUE), TextView::new),
            new ViewSpec("gamecontroller", "GameController", "Referee a practice game: format, teams, destinations; "
                    + "state, clock, set plays, penalties, cards and robots' liveness; match mode and its override.",
                    Set.of(), touchline.ui.referee.GameControllerTab::new, 1240), // HSL: both teams side by side
            new ViewSpec("gc-robots", "GameController's robots", "Each robot as the field's HSL GameController sees "
                    + "it (return packets: fallen, pose, ball; liveness), with --gc-monitor HOST.", Set.of(),
                    (c, s) -> new touchline.ui.referee.GcRobotsView(c)),
            new ViewSpec("nao", "NAO", "Connect to a NAO: connection state, method browser with typed parameters, "
                    + "stand/sit/turn head/say, walk with W A S D Q E, camera.", Set.of(), touchline.ui.nao.NaoView::new,
                    850), // the connection row up to Connect
            new ViewSpec("replay", "Record & replay", "Record the session to MCAP; open a recording, play, seek by "
                    + "timeline or event, loop, speed; live listening; load team schemas.", Set.of(), (c, s) -> new ReplayView(c)),
            new ViewSpec("viewers", "Viewers", "Serve this console to remote viewers (Foxglove, Lichtblick, another "
                    + "Touchline: console --connect URL); the URL with its token, each viewer's subscriptions, rate and "
                    + "drops. Ctrl+Shift+V switches serving on and off.", Set.of(), (c, s) -> new touchline.ui.viewers.ViewersView(c)),
            new ViewSpec("parameters", "Parameters", "The ROS 2 robots' parameters through their Foxglove bridges: "
                    + "Refresh reads them, Set writes a typed value, Space or a double-click toggles a bool; held during "
                    + "play like a debug option.", Set.of(), (c, s) -> new touchline.ui.ros2.ParametersView(c)),
            new ViewSpec("ros-commands", "ROS 2 publish & call", "Publish a message on a ROS 2 robot's topic (typed as "
                    + "JSON; sent as CDR when the robot takes it) or call its service and read its answers; held during "
                    + "play like a debug option.", Set.of(),
                    (c, s) -> new touchline.ui.ros2.RosCommandsView(c)),
            new ViewSpec(RAW, "Raw data", "The newest message of an option whose kind no view knows, as protobuf "
                    + "text.", Set.of(), RawDataView::new));

    public List<ViewSpec> all() {
        return specs;
    }

    public Optional<ViewSpec> byId(String id) {
        return specs.stream().filter(s -> s.id().equals(id)).findFirst();
    }

    /** The visualisation for a DebugKind number; unknown kinds get the raw view. */
    public Optional<ViewSpec> forKind(int kind) {
        Optional<ViewSpec> v = specs.stream().filter(s -> s.kinds().contains(kind)).findFirst();
        return v.isPresent() ? v : byId(RAW);
    }
}
