package touchline.ui.render;

/**
 * JavaFX settings every window start applies before the toolkit starts (the console command's
 * {@code cli.FxThread} and the plain {@link Launcher} alike): how it repaints, and which of its log
 * lines reach the user's terminal; a {@code -D} or logging configuration of the user's wins.
 */
public final class RenderDefaults {

    /**
     * How many separate changed areas JavaFX repaints in one frame before it merges them: its 6
     * merged the plot, the debug console and the status bar into boxes painted from the window's
     * root, every background under them included; 12 keeps each view's change its own (the most
     * is 15; docs/archive/benchmarks-sessions.md "Twelfth session").
     */
    static final String DIRTY_REGIONS = "12";

    /**
     * JavaFX's controls log "index exceeds maxCellCount" at INFO each time a list holding more lines
     * than its height has pixels is laid out at its end (its VirtualFlow compares a line's index with
     * the viewport's length in pixels and stops adding empty rows, which is all it should do): about
     * nine lines a minute in the user's terminal while the debug console follows. Kept to warnings.
     * Held here: the logging system keeps only a weak reference to a logger, and a collected one
     * forgets its level.
     */
    static final java.util.logging.Logger CONTROLS_LOG = java.util.logging.Logger.getLogger("javafx.scene.control");

    /**
     * JavaFX warns at every start that it runs from the class path ("Unsupported JavaFX configuration:
     * classes were loaded from 'unnamed module …'"): the launcher's choice, known and tested, and a
     * WARNING the user can do nothing about. That one line is dropped; JavaFX's other warnings show.
     */
    static final java.util.logging.Logger JAVAFX_LOG = java.util.logging.Logger.getLogger("javafx");
    static final String CLASS_PATH_WARNING = "Unsupported JavaFX configuration";

    /** Sets what the user has not set (a level or filter from a logging configuration stays). */
    public void apply() {
        if (System.getProperty("prism.dirtyregioncount") == null) {
            System.setProperty("prism.dirtyregioncount", DIRTY_REGIONS);
        }
        if (CONTROLS_LOG.getLevel() == null) {
            CONTROLS_LOG.setLevel(java.util.logging.Level.WARNING);
        }
        if (JAVAFX_LOG.getFilter() == null) {
            JAVAFX_LOG.setFilter(r -> r.getMessage() == null || !r.getMessage().startsWith(CLASS_PATH_WARNING));
        }
    }
}
