package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import java.util.HexFormat;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * What both HSL formats must do with the official GameController's datagrams: every step file
 * decodes to the values of its README, every file and every datagram of the game's stream
 * encodes back to the same bytes, and the network recogniser names the right format.
 */
abstract class HslGoldenChecks {

    private final HslGolden golden;
    private final GameStateFormat format;
    private final GameStateFormat trueData;
    private final int version;
    private final int substitute;

    HslGoldenChecks(String folder, GameStateFormat format, GameStateFormat trueData, int substitute) {
        this.golden = new HslGolden(folder);
        this.format = format;
        this.trueData = trueData;
        this.version = format.version();
        this.substitute = substitute;
    }

    private GameControlData decode(GameStateFormat f, String file) {
        byte[] bytes = golden.bytes(file);
        assertEquals(f.size(), bytes.length, file);
        Decoded<GameControlData> d = f.decode(bytes);
        assertTrue(d.isOk(), file + ": " + d);
        return d.value();
    }

    @Test
    void everyStepFileDecodesToTheValuesOfTheReadme() {
        assertTrue(golden.steps.size() >= 50, "README rows read: " + golden.steps.size());
        assertEquals(golden.steps.keySet(), golden.teams.keySet());
        assertTrue(golden.players.values().stream().mapToInt(List::size).sum() > 20, "README player rows read");
        for (HslGolden.Step s : golden.steps.values()) {
            GameControlData d = decode(format, s.file());
            String f = s.file();
            assertEquals(s.packetNumber(), d.packetNumber(), f);
            assertEquals(5, d.playersPerTeam(), f);
            assertEquals(1, d.competitionType(), f + " MIDDLE");
            assertEquals(s.stopped() == 1, d.stopped(), f + " stopped");
            assertEquals(s.gamePhase(), d.gamePhase(), f + " gamePhase");
            assertGame(s, d);
            assertEquals(s.firstHalf() == 1, d.firstHalf(), f);
            assertTeams(f, d);
        }
    }

    private void assertGame(HslGolden.Step s, GameControlData d) {
        String f = s.file();
        assertEquals(s.state(), GameControlData.stateName(d.state()), f + " state");
        HslSetPlay setPlay = HslSetPlay.ofSecondaryState(d.secondaryState());
        assertEquals(s.setPlay(), setPlay.name(), f + " setPlay");
        int kicking = setPlay == HslSetPlay.NONE ? d.kickOffTeam() : d.setPlayTeam();
        assertEquals(s.kickingTeam() == 255 ? GameControlData.DROP_BALL : s.kickingTeam(), kicking, f + " kickingTeam");
        assertEquals(s.secsRemaining(), d.secsRemaining(), f + " secsRemaining");
        assertEquals(s.secondaryTime(), d.secondaryTime(), f + " secondaryTime");
    }

    private void assertTeams(String f, GameControlData d) {
        List<HslGolden.Team> expected = golden.teams.get(f);
        for (int t = 0; t < 2; t++) {
            HslGolden.Team e = expected.get(t);
            TeamInfo team = d.teams().get(t);
            assertEquals(e.number(), team.teamNumber(), f);
            assertEquals(e.colour(), TeamColour.ofWire(team.colour()).name(), f + " colour");
            assertEquals(e.goalkeeperColour(), TeamColour.ofWire(team.goalkeeperColour()).name(), f);
            assertTrue(team.player(e.goalkeeper()).goalkeeper(), f + " goalkeeper");
            assertEquals(1, team.players().stream().filter(RobotInfo::goalkeeper).count(), f);
            assertEquals(e.score(), team.score(), f + " score");
            assertEquals(e.budget(), team.messageBudget(), f + " messageBudget");
            assertEquals(0, team.penaltyShot(), f);
            assertEquals(0, team.singleShots(), f);
            for (int p = 1; p <= 20; p++) {
                assertPlayer(f, team, p);
            }
        }
    }

    private void assertPlayer(String f, TeamInfo team, int number) {
        RobotInfo r = team.player(number);
        HslGolden.Player listed = golden.players.get(f).stream()
                .filter(p -> p.team() == team.teamNumber() && p.number() == number).findFirst().orElse(null);
        String who = f + " team " + team.teamNumber() + " player " + number;
        HslPenalty penalty = HslPenalty.ofNeutral(r.penalty());
        if (listed != null) {
            assertEquals(listed.penaltyName(), penalty.name(), who);
            assertEquals(listed.penalty(), penalty.wire(version), who);
            assertEquals(listed.secs(), r.secsTillUnpenalised(), who);
            assertEquals(listed.warnings(), r.warnings(), who);
            assertEquals(listed.cautions(), r.cautions(), who);
        } else {
            assertEquals(number > 5 ? HslPenalty.SUBSTITUTE : HslPenalty.NONE, penalty, who);
            assertEquals(number > 5 ? substitute : 0, penalty.wire(version), who);
            assertEquals(0, r.secsTillUnpenalised(), who);
            assertEquals(0, r.cautions(), who);
            assertEquals(0, r.warnings(), who);
        }
    }

    @Test
    void monitorCopiesCarryTheTrueState() {
        assertEquals(6, golden.monitorSteps.size());
        for (HslGolden.Step s : golden.monitorSteps.values()) {
            GameControlData d = decode(trueData, s.file());
            assertGame(s, d);
            assertEquals(DecodeFailure.WRONG_MAGIC, format.decode(golden.bytes(s.file())).failure(), s.file());
            // the robots' datagram of the same instant still shows the fake SET
            GameControlData robots = decode(format, s.file().replace(".monitor", ""));
            assertEquals(GameControlData.STATE_SET, robots.state(), s.file());
            assertEquals(GameControlData.STATE_PLAYING, d.state(), s.file());
        }
    }

    @Test
    void everyFileAndEveryStreamDatagramEncodesBackToTheSameBytes() {
        List<String> files = golden.binFiles();
        assertEquals(golden.steps.size() + golden.monitorSteps.size(), files.size());
        for (String file : files) {
            GameStateFormat f = file.endsWith(".monitor.bin") ? trueData : format;
            assertEquals(HexFormat.of().formatHex(golden.bytes(file)), HexFormat.of().formatHex(f.encode(decode(f, file))),
                    file);
        }
        List<byte[]> stream = golden.stream(format.size());
        assertEquals(1609, stream.size());
        for (int i = 0; i < stream.size(); i++) {
            Decoded<GameControlData> d = format.decode(stream.get(i));
            assertTrue(d.isOk(), "stream datagram " + i + ": " + d);
            assertEquals(HexFormat.of().formatHex(stream.get(i)), HexFormat.of().formatHex(format.encode(d.value())),
                    "stream datagram " + i);
        }
    }

    @Test
    void theNetworkRecogniserNamesTheFormatByVersionNotBySize() {
        KnownGameStateFormats known = new KnownGameStateFormats();
        for (String file : golden.binFiles()) {
            KnownGameStateFormats.Match m = known.decode(golden.bytes(file));
            assertNotNull(m, file);
            boolean monitor = file.endsWith(".monitor.bin");
            assertEquals(monitor ? trueData.kind() : format.kind(), m.format().kind(), file);
            assertEquals(monitor, m.format().isTrueData(), file);
        }
        assertFalse(new GameState8().decode(golden.bytes("00-initial.bin")).isOk(), "never read as the 2014 v8");
    }

    @Test
    void setPlaysAndPenaltiesKeepTheirNamesThroughTheNeutralCodes() {
        for (HslSetPlay p : HslSetPlay.values()) {
            assertSame(p, HslSetPlay.ofWire(p.wire()));
            assertSame(p, HslSetPlay.ofSecondaryState(p.secondaryState()));
        }
        for (HslPenalty p : HslPenalty.values()) {
            assertSame(p, HslPenalty.ofNeutral(p.neutral()));
            HslPenalty back = HslPenalty.ofWire(version, p.wire(version));
            assertSame(back == p ? p : HslPenalty.PICK_UP, back, p.name());
        }
    }
}
