package touchline.ui;

/**
 * JavaFX settings every window start applies before the toolkit starts (the console command's
 * {@code cli.FxThread} and the plain {@link Launcher} alike); a {@code -D} of the user's wins.
 */
public final class RenderDefaults {

    /**
     * How many separate changed areas JavaFX repaints in one frame before it merges them: its 6
     * merged the plot, the debug console and the status bar into boxes painted from the window's
     * root, every background under them included; 12 keeps each view's change its own (the most
     * is 15; docs/benchmarks.md "Twelfth session").
     */
    static final String DIRTY_REGIONS = "12";

    /** Sets what the user has not set. */
    public void apply() {
        if (System.getProperty("prism.dirtyregioncount") == null) {
            System.setProperty("prism.dirtyregioncount", DIRTY_REGIONS);
        }
    }
}
