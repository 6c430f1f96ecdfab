package touchline.app.bridges;

import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.*;

class TeamFileTest {

    @Test
    void theSampleTeamNamesThreeBridgesAndAMapping() throws IOException {
        TeamFile team = TeamFile.read(Path.of("samples/ros2-team.json"));
        assertEquals(3, team.robots().size());
        assertEquals(new BridgeAddress("booster-2", java.net.URI.create("ws://127.0.0.1:8772/")), team.robots().get(1));
        assertTrue(team.mapping().problems().isEmpty(), team.mapping().problems().toString());
    }

    @Test
    void aBridgeIsAUrlOrANameAndAUrlAndAnythingElseIsSaidInWords() {
        assertEquals("booster-1", BridgeAddress.parse("booster-1=ws://10.0.0.11:8765/").name());
        assertEquals("10.0.0.11:8765", BridgeAddress.parse("ws://10.0.0.11:8765/").name());
        assertEquals("10.0.0.12:8765", BridgeAddress.parse("ws://10.0.0.12/?a=b").name(), "the default port");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> BridgeAddress.parse("http://10.0.0.11:8765/"));
        assertTrue(e.getMessage().startsWith("not a WebSocket URL"), e.getMessage());
    }

    @Test
    void aTeamFileWithoutRobotsOrWithAnUnknownMappingLineSaysSo() throws IOException {
        IllegalArgumentException none = assertThrows(IllegalArgumentException.class, () -> TeamFile.parse("{}"));
        assertTrue(none.getMessage().startsWith("no \"robots\""), none.getMessage());
        TeamFile t = TeamFile.parse("{\"robots\":[{\"url\":\"ws://h:1/\"}],\"mapping\":{\"colour\":\"red\"}}");
        assertEquals("h:1", t.robots().get(0).name());
        assertEquals(1, t.mapping().problems().size());
    }
}
