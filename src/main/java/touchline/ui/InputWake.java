package touchline.ui;

import javafx.collections.ListChangeListener;
import javafx.event.EventHandler;
import javafx.scene.Scene;
import javafx.scene.input.InputEvent;
import javafx.stage.Window;

/**
 * Wakes the idle frame pulse when the user touches any of the console's windows (the main one,
 * a view dragged out into its own window, Ctrl+K): a key, a click, a scroll or a mouse move
 * may change what a view shows (a filter typed, a tab chosen) without any data arriving.
 */
final class InputWake implements AutoCloseable {

    private final EventHandler<InputEvent> filter;
    private final ListChangeListener<Window> windows = this::windowsChanged;
    private final javafx.beans.value.ChangeListener<Scene> scenes = (o, was, now) -> watch(was, now);

    InputWake(Runnable wake) {
        this.filter = e -> wake.run();
        Window.getWindows().forEach(this::watch);
        Window.getWindows().addListener(windows);
    }

    private void windowsChanged(ListChangeListener.Change<? extends Window> c) {
        while (c.next()) {
            c.getAddedSubList().forEach(this::watch);
            c.getRemoved().forEach(w -> {
                w.sceneProperty().removeListener(scenes);
                watch(w.getScene(), null);
            });
        }
    }

    private void watch(Window w) {
        w.sceneProperty().addListener(scenes);
        watch(null, w.getScene());
    }

    private void watch(Scene was, Scene now) {
        if (was != null) {
            was.removeEventFilter(InputEvent.ANY, filter);
        }
        if (now != null) {
            now.removeEventFilter(InputEvent.ANY, filter); // once per scene, however often it is seen
            now.addEventFilter(InputEvent.ANY, filter);
        }
    }

    @Override
    public void close() {
        Window.getWindows().removeListener(windows);
        for (Window w : Window.getWindows()) {
            w.sceneProperty().removeListener(scenes);
            watch(w.getScene(), null);
        }
    }
}
