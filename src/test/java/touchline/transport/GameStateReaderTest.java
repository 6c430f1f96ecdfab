package touchline.transport;

import org.junit.jupiter.api.Test;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.KnownGameStateFormats;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The one recognition of the game state an envelope carries, on the real HSL v20 golden packets. */
class GameStateReaderTest {

    private static final Path HSL20 = Path.of("src/test/resources/golden/gamecontroller/hsl20");

    private static Envelope envelope(Channel channel, byte[] raw, String error) {
        return new Envelope(1, Direction.IN, channel, null, Envelope.NO_ROBOT, "gc.hsl20", null, raw, error);
    }

    @Test
    void aWellFormedGameControllerPacketIsReadInItsFormat() throws Exception {
        byte[] set = Files.readAllBytes(HSL20.resolve("04-set.bin"));
        KnownGameStateFormats.Match m = new GameStateReader().read(envelope(Channel.GAMECONTROLLER, set, null));
        assertEquals("gc.hsl20", m.format().kind());
        assertEquals(GameControlData.STATE_SET, m.data().state());
        byte[] monitor = Files.readAllBytes(HSL20.resolve("05-playing-delayed.monitor.bin"));
        KnownGameStateFormats.Match trueData = new GameStateReader().read(envelope(Channel.GAMECONTROLLER, monitor, null));
        assertTrue(trueData.format().isTrueData());
        assertEquals(GameControlData.STATE_PLAYING, trueData.data().state());
    }

    @Test
    void whatTheLivePathFlaggedOrAnotherChannelOrAnUnknownPacketCarriesNone() throws Exception {
        byte[] set = Files.readAllBytes(HSL20.resolve("04-set.bin"));
        GameStateReader reader = new GameStateReader();
        assertNull(reader.read(envelope(Channel.GAMECONTROLLER, set, "game state from 10.0.0.9:3838, not the field's")));
        assertFalse(GameStateReader.isGameState(envelope(Channel.GAMECONTROLLER, set, "intruder")));
        assertNull(reader.read(envelope(Channel.FUMANOID, set, null)));
        assertNull(reader.read(envelope(Channel.GAMECONTROLLER, new byte[]{'R', 'G', 'r', 't', 4, 0}, null)), "a return packet");
        assertNull(reader.read(envelope(Channel.GAMECONTROLLER, new byte[]{'R', 'G', 'm', 'e', 20}, null)), "cut short");
        assertTrue(GameStateReader.isGameState(envelope(Channel.GAMECONTROLLER, new byte[]{'R', 'G', 'm', 'e', 20}, null)));
    }
}
