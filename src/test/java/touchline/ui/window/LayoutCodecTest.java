package touchline.ui.window;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class LayoutCodecTest {

    private final LayoutCodec codec = new LayoutCodec();

    static final LayoutNode.Leaf LEFT = new LayoutNode.Leaf(1,
            List.of(new LayoutNode.Entry("robots", ""), new LayoutNode.Entry("options", "")));
    static final LayoutNode.Branch RIGHT = new LayoutNode.Branch(true, List.of(0.5), List.of(
            new LayoutNode.Leaf(0, List.of(new LayoutNode.Entry("plot", "3/demo.plotter"))),
            new LayoutNode.Leaf(0, List.of(new LayoutNode.Entry("field", "")))));
    static final List<LayoutNode> LAYOUT = List.of(
            new LayoutNode.Branch(false, List.of(0.35), List.of(LEFT, RIGHT)),
            new LayoutNode.Leaf(0, List.of(new LayoutNode.Entry("network", ""))));

    @Test
    void writesAndReadsBackEveryWindowSplitAndView() {
        String text = codec.write(LAYOUT);
        assertTrue(text.startsWith(LayoutCodec.HEADER));
        assertEquals(LAYOUT, codec.read(text));
    }

    @Test
    void skipsWhatItDoesNotUnderstand() {
        List<LayoutNode> read = codec.read("""
                touchline-layout 1
                # a comment
                window
                 hologram 3
                  view robots
                 leaf x
                  view
                  view options
                  teleport now
                """);
        assertEquals(List.of(new LayoutNode.Leaf(0, List.of(new LayoutNode.Entry("options", "")))), read);
        assertEquals(List.of(), codec.read("garbage\n\u0000\n"));
    }

    @Test
    void storesNamedLayoutsAsFiles(@TempDir Path dir) throws Exception {
        LayoutStore store = new LayoutStore(dir.resolve("layouts"));
        assertTrue(store.names().isEmpty());
        store.save("match/day 1", LAYOUT);
        assertEquals(List.of("match_day 1"), store.names());
        assertEquals(LAYOUT, store.load("match/day 1").orElseThrow());
        assertTrue(store.load("nothing").isEmpty());
        Files.writeString(dir.resolve("layouts").resolve("broken.layout"), "window\n leaf 0\n  view rob");
        assertEquals(List.of(new LayoutNode.Leaf(0, List.of(new LayoutNode.Entry("rob", "")))),
                store.load("broken").orElseThrow());
    }
}
