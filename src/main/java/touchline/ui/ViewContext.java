package touchline.ui;

import touchline.app.Console;
import touchline.model.store.ViewStores;

import java.nio.file.Path;
import java.util.function.BiConsumer;

/**
 * The collaborators every view gets through its constructor: the application core, the
 * view stores, the registry of views and a way to open one (the options tree opens
 * visualisations), and the directory of the user's settings where a view may remember what
 * the user typed (null: nothing is remembered, as in a view test), and the window's serving to
 * remote viewers.
 */
public record ViewContext(Console console, ViewStores stores, ViewRegistry registry,
                          BiConsumer<ViewSpec, ViewSource> opener, Path settingsDir, ServeToggle serving) {

    public ViewContext(Console console, ViewStores stores, ViewRegistry registry,
                       BiConsumer<ViewSpec, ViewSource> opener, Path settingsDir) {
        this(console, stores, registry, opener, settingsDir, new ServeToggle(console));
    }

    public ViewContext(Console console, ViewStores stores, ViewRegistry registry,
                       BiConsumer<ViewSpec, ViewSource> opener) {
        this(console, stores, registry, opener, null);
    }

    public void open(ViewSpec spec, ViewSource source) {
        opener.accept(spec, source);
    }
}
