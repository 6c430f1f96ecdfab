package touchline.ui.render;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The JavaFX settings a window start applies: set when the user set nothing, the user's kept. */
class RenderDefaultsTest {

    private static final String KEY = "prism.dirtyregioncount";
    private String before;

    @BeforeEach
    void remember() {
        before = System.getProperty(KEY);
    }

    @AfterEach
    void restore() {
        if (before == null) {
            System.clearProperty(KEY);
        } else {
            System.setProperty(KEY, before);
        }
    }

    @Test
    void setsTheDirtyRegionCountWhenTheUserDidNot() {
        System.clearProperty(KEY);
        new RenderDefaults().apply();
        assertEquals(RenderDefaults.DIRTY_REGIONS, System.getProperty(KEY));
    }

    @Test
    void keepsTheUsersOwn() {
        System.setProperty(KEY, "3");
        new RenderDefaults().apply();
        assertEquals("3", System.getProperty(KEY));
    }

    /**
     * The controls' "index exceeds maxCellCount" note (INFO) stays out of the user's terminal, their
     * warnings do not; a level the user configured stays.
     */
    @Test
    void keepsTheControlsNotesOutOfTheTerminalButNotTheirWarnings() {
        java.util.logging.Logger controls = java.util.logging.Logger.getLogger("javafx.scene.control");
        java.util.logging.Level was = controls.getLevel();
        try {
            controls.setLevel(null);
            assertTrue(controls.isLoggable(java.util.logging.Level.INFO), "JUL's default before");
            new RenderDefaults().apply();
            assertFalse(controls.isLoggable(java.util.logging.Level.INFO));
            assertTrue(controls.isLoggable(java.util.logging.Level.WARNING));
            controls.setLevel(java.util.logging.Level.FINE);
            new RenderDefaults().apply();
            assertEquals(java.util.logging.Level.FINE, controls.getLevel(), "the user's own level");
        } finally {
            controls.setLevel(was);
        }
    }

    /** JavaFX's "runs from the class path" warning at every start is dropped; its other warnings are not. */
    @Test
    void dropsJavaFxsClassPathWarningAndNoOther() {
        java.util.logging.Logger javafx = java.util.logging.Logger.getLogger("javafx");
        java.util.logging.Filter was = javafx.getFilter();
        java.util.List<String> seen = new java.util.ArrayList<>();
        java.util.logging.Handler catcher = new java.util.logging.Handler() {
            @Override
            public void publish(java.util.logging.LogRecord r) {
                seen.add(r.getMessage());
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        javafx.addHandler(catcher);
        try {
            javafx.setFilter(null);
            new RenderDefaults().apply();
            javafx.warning("Unsupported JavaFX configuration: classes were loaded from 'unnamed module @1dd02175'");
            javafx.warning("Loading FXML document with JavaFX API of version 22 by JavaFX runtime of version 21");
            assertEquals(java.util.List.of("Loading FXML document with JavaFX API of version 22 by JavaFX runtime of version 21"), seen);
        } finally {
            javafx.removeHandler(catcher);
            javafx.setFilter(was);
        }
    }
}
