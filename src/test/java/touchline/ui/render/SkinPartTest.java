package touchline.ui.render;

import javafx.geometry.Orientation;
import javafx.scene.Scene;
import javafx.scene.control.ListView;
import javafx.scene.control.ScrollBar;
import javafx.scene.control.skin.ListViewSkin;
import javafx.scene.layout.VBox;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.testfx.api.FxToolkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static touchline.testing.FxStep.fx;

/** A node of a control's skin, found once by its selector and kept until the skin replaces it. */
class SkinPartTest {

    @BeforeAll
    static void toolkit() throws Exception {
        FxToolkit.registerPrimaryStage();
    }

    private static ListView<String> list() {
        ListView<String> list = new ListView<>();
        new Scene(new VBox(list), 300, 200);
        list.applyCss();
        list.getParent().layout();
        return list;
    }

    @Test
    void findsTheNodeThatMatchesAndKeepsIt() throws Exception {
        fx(() -> {
            ListView<String> list = list();
            SkinPart<ScrollBar> upright = new SkinPart<>(list, ".scroll-bar", ScrollBar.class,
                    b -> b.getOrientation() == Orientation.VERTICAL);
            SkinPart<ScrollBar> sideways = new SkinPart<>(list, ".scroll-bar", ScrollBar.class,
                    b -> b.getOrientation() == Orientation.HORIZONTAL);
            assertEquals(Orientation.VERTICAL, upright.get().getOrientation());
            assertEquals(Orientation.HORIZONTAL, sideways.get().getOrientation(), "the one the test picks, not the first match");
            assertSame(upright.get(), upright.get(), "kept");
            return null;
        });
    }

    @Test
    void aNewSkinsNodeIsFoundAgain() throws Exception {
        fx(() -> {
            ListView<String> list = list();
            SkinPart<javafx.scene.control.skin.VirtualFlow> flow = new SkinPart<>(list, ".virtual-flow",
                    javafx.scene.control.skin.VirtualFlow.class);
            var first = flow.get();
            assertNotNull(first);
            list.setSkin(new ListViewSkin<>(list));
            list.applyCss();
            list.getParent().layout();
            assertNotSame(first, flow.get(), "the old skin's flow left the list");
            assertNotNull(flow.get());
            return null;
        });
    }

    @Test
    void nothingWhileTheControlHasNoSuchNode() throws Exception {
        fx(() -> {
            ListView<String> list = new ListView<>(); // no scene, no skin
            assertNull(new SkinPart<>(list, ".virtual-flow", javafx.scene.control.skin.VirtualFlow.class).get());
            return null;
        });
    }
}
