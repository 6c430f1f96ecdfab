package touchline.ui.window;

import javafx.collections.ListChangeListener;
import javafx.event.Event;
import javafx.event.EventHandler;
import javafx.event.EventType;
import javafx.scene.Scene;
import javafx.stage.Window;

/**
 * One event filter on every window of the application, present and future (the main window, a
 * view dragged out into its own window, Ctrl+K, dialogs, help): the window uses it to wake its
 * idle frame pulse on any key, click, scroll or mouse move (a filter typed, a tab chosen may
 * change what a view shows without any data arriving) and to answer F1 everywhere.
 */
final class EveryWindow<E extends Event> implements AutoCloseable {

    /** What the filter is given: the event and the window it reached. */
    interface Handler<E> {
        void handle(E event, Window window);
    }

    private final EventType<E> type;
    private final Handler<E> handler;
    private final java.util.Map<Scene, EventHandler<E>> filters = new java.util.HashMap<>();
    private final ListChangeListener<Window> windows = this::windowsChanged;
    private final javafx.beans.value.ChangeListener<Scene> scenes = (o, was, now) -> {
        unwatch(was);
        if (now != null) {
            watch(now);
        }
    };

    /** FX thread. */
    EveryWindow(EventType<E> type, Handler<E> handler) {
        this.type = type;
        this.handler = handler;
        Window.getWindows().forEach(this::watch);
        Window.getWindows().addListener(windows);
    }

    private void windowsChanged(ListChangeListener.Change<? extends Window> c) {
        while (c.next()) {
            c.getAddedSubList().forEach(this::watch);
            c.getRemoved().forEach(w -> {
                w.sceneProperty().removeListener(scenes);
                unwatch(w.getScene());
            });
        }
    }

    private void watch(Window w) {
        w.sceneProperty().removeListener(scenes);
        w.sceneProperty().addListener(scenes);
        if (w.getScene() != null) {
            watch(w.getScene());
        }
    }

    private void watch(Scene scene) {
        filters.computeIfAbsent(scene, s -> {
            EventHandler<E> f = e -> handler.handle(e, s.getWindow());
            s.addEventFilter(type, f);
            return f;
        });
    }

    private void unwatch(Scene scene) {
        EventHandler<E> f = scene == null ? null : filters.remove(scene);
        if (f != null) {
            scene.removeEventFilter(type, f);
        }
    }

    @Override
    public void close() {
        Window.getWindows().removeListener(windows);
        for (Window w : Window.getWindows()) {
            w.sceneProperty().removeListener(scenes);
        }
        new java.util.ArrayList<>(filters.keySet()).forEach(this::unwatch);
    }
}
