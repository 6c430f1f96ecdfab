package touchline.ui.window;

import touchline.app.LiveField;
import touchline.app.Naos;
import touchline.app.OptionSwitches;
import touchline.app.Recordings;
import touchline.app.Referee;
import touchline.app.RemoteView;
import touchline.app.Replays;
import touchline.app.TeamBudget;
import touchline.app.TeamSchemas;
import touchline.app.bridges.RosBridges;
import touchline.model.store.ViewStores;

import java.nio.file.Path;
import java.util.function.BiConsumer;
import touchline.ui.frame.ConsoleStatus;
import touchline.ui.frame.ViewSource;
import touchline.ui.viewers.ServeToggle;

/**
 * What a view may be handed through its constructor: the core's use-case services (a view takes
 * the one or two it needs, never the core's composition root), the registry of views and a way
 * to open one (the options tree opens visualisations), the directory of the user's settings where
 * a view may remember what the user typed (null: nothing is remembered, as in a view test), and
 * the window's serving to remote viewers. {@code ConsoleWindow} makes the one of a window.
 */
public record ViewContext(LiveField field, OptionSwitches switches, Referee referee, Naos naos, Recordings recordings,
                          Replays replays, TeamSchemas schemas, TeamBudget budget, RemoteView remote,
                          RosBridges bridges,
                          ViewRegistry registry, BiConsumer<ViewSpec, ViewSource> opener, Path settingsDir,
                          ServeToggle serving) {

    /** The bounded stores the views pull from once per frame (the replay's while one is open). */
    public ViewStores stores() {
        return field.stores();
    }

    /** What the status bar and the GameController tab say about the console as a whole. */
    public ConsoleStatus status() {
        return new ConsoleStatus(field, referee, replays, remote);
    }

    public void open(ViewSpec spec, ViewSource source) {
        opener.accept(spec, source);
    }
}
