package touchline.ui;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

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
}
