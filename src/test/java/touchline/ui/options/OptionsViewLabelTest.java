package touchline.ui.options;

import org.junit.jupiter.api.Test;
import touchline.model.OptionState;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The Debug options view says an option's "in the game" place and whether the robot confirmed it. */
class OptionsViewLabelTest {

    private static OptionState option(int rank, int onRobot) {
        return new OptionState("demo.field", "", 8, false, false, false, rank, onRobot);
    }

    @Test
    void theGamePlaceIsShownAskedUntilTheRobotConfirmsIt() {
        assertEquals("demo.field   FIELD", OptionsView.label(option(0, 0)));
        assertEquals("demo.field   FIELD · in the game #2 asked", OptionsView.label(option(2, 0)));
        assertEquals("demo.field   FIELD · in the game #2 (confirmed)", OptionsView.label(option(2, 2)));
        assertEquals("demo.field   FIELD · out of the game asked", OptionsView.label(option(0, 1)));
    }
}
