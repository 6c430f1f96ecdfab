package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The one source of the game-state names: the GameController's words, read back, and which are play. */
class GameStateNamesTest {

    @Test
    void everyNamedStateReadsBackToItsCode() {
        String[] names = {"INITIAL", "READY", "SET", "PLAYING", "FINISHED", "STANDBY"};
        for (int code = 0; code < names.length; code++) {
            assertEquals(names[code], GameControlData.stateName(code));
            assertEquals(code, GameControlData.stateCode(names[code]));
        }
        assertEquals(GameControlData.STATE_PLAYING, GameControlData.stateCode("PLAYING"));
        assertEquals(GameControlData.STATE_STANDBY, GameControlData.stateCode("STANDBY"));
    }

    @Test
    void aCodeWithoutANameIsShownAsItsNumberAndAWordThatIsNoStateHasNoCode() {
        assertEquals("STATE9", GameControlData.stateName(9));
        assertEquals("STATE-1", GameControlData.stateName(-1));
        assertEquals(-1, GameControlData.stateCode("playing"), "names are the GameController's, in capitals");
        assertEquals(-1, GameControlData.stateCode("STATE9"));
        assertEquals(-1, GameControlData.stateCode(""));
        assertEquals(-1, GameControlData.stateCode(null));
    }

    @Test
    void readySetAndPlayingArePlay() {
        assertTrue(GameControlData.isPlay(GameControlData.STATE_READY));
        assertTrue(GameControlData.isPlay(GameControlData.STATE_SET));
        assertTrue(GameControlData.isPlay(GameControlData.STATE_PLAYING));
        assertFalse(GameControlData.isPlay(GameControlData.STATE_INITIAL));
        assertFalse(GameControlData.isPlay(GameControlData.STATE_FINISHED));
        assertFalse(GameControlData.isPlay(GameControlData.STATE_STANDBY));
        assertFalse(GameControlData.isPlay(-1));
    }
}
