package touchline.transport.nao;

import org.junit.jupiter.api.Test;

import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class WalkInputTest {

    @Test
    void keysMapToNormalisedVelocities() {
        assertEquals(new WalkInput(0.5f, 0, 0), WalkInput.fromKeys(Set.of('W'), 0.5f));
        assertEquals(new WalkInput(0, -1, 1), WalkInput.fromKeys(Set.of('D', 'Q'), 2f));
        assertTrue(WalkInput.fromKeys(Set.of('W', 'S'), 1f).isStop(), "opposite keys cancel");
    }

    @Test
    void axesHaveADeadZoneAndAreClamped() {
        assertTrue(WalkInput.fromAxes(0.1f, -0.1f, 0.05f).isStop());
        assertEquals(new WalkInput(1, -0.5f, 0), WalkInput.fromAxes(3f, -0.5f, Float.NaN));
    }
}
