package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** HSL v20 (158 bytes) against the official GameController 7.0.0-rc.3's datagrams. */
class HslGameState20Test extends HslGoldenChecks {

    HslGameState20Test() {
        super("hsl20", new HslGameState20(), HslGameState20.trueData(), 13);
    }

    @Test
    void sizesFollowFromTheHeader() {
        assertEquals(158, HslGameState20.SIZE);
        assertEquals(158, new HslGameState20().size());
        assertEquals(20, new HslGameState20().version());
    }
}
