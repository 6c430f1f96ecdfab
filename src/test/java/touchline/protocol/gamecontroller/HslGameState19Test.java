package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** HSL v19 (198 bytes) against the official GameController 6.0.1's datagrams. */
class HslGameState19Test extends HslGoldenChecks {

    HslGameState19Test() {
        super("hsl19", new HslGameState19(), HslGameState19.trueData(), 11);
    }

    @Test
    void sizesFollowFromTheHeader() {
        assertEquals(198, HslGameState19.SIZE);
        assertEquals(19, new HslGameState19().version());
    }
}
