package touchline.ui;

import touchline.app.Console;
import touchline.model.store.ViewStores;

import java.util.function.BiConsumer;

/**
 * The collaborators every view gets through its constructor: the application core, the
 * view stores, the registry of views and a way to open one (the options tree opens
 * visualisations).
 */
public record ViewContext(Console console, ViewStores stores, ViewRegistry registry,
                          BiConsumer<ViewSpec, ViewSource> opener) {

    public void open(ViewSpec spec, ViewSource source) {
        opener.accept(spec, source);
    }
}
