package touchline.transport.gamecontroller;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import touchline.game.ManualClock;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslGameGoldenTest;
import touchline.game.hsl.HslGoldenScript;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.protocol.gamecontroller.HslGameState19;
import touchline.protocol.gamecontroller.HslGameState20;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

/**
 * Reproduces the whole official datagram stream of the golden games ({@code stream.bin}, 1609
 * datagrams over 800 s, with the send times and packet numbers of {@code stream-times.csv}):
 * the game runs the README's script on a manual clock and {@link SendSchedule#burstOnStop}
 * decides when a datagram goes out. Every datagram is compared byte for byte with its time
 * and number; a failure lists the first differing datagrams with field names.
 */
class HslStreamGoldenTest {

    private static final int DATAGRAMS = 1609;

    @ParameterizedTest(name = "version {0}")
    @ValueSource(ints = {20, 19})
    void theWholeStreamIsReproducedWithItsTimesAndNumbers(int version) throws IOException {
        int size = version == 20 ? HslGameState20.SIZE : HslGameState19.SIZE;
        byte[] stream = HslGameGoldenTest.golden(version, "stream.bin");
        assertEquals(DATAGRAMS * size, stream.length, "stream.bin length");
        long[][] times = times(version);
        assertEquals(DATAGRAMS, times.length, "stream-times.csv rows");

        ManualClock clock = new ManualClock(0);
        HslGame game = HslGameGoldenTest.goldenGame(version, clock);
        GameStateFormat format = version == 20 ? new HslGameState20() : new HslGameState19();
        SendSchedule schedule = SendSchedule.burstOnStop(0, GcConfig.INTERVAL_MS, GcSender.BURST_SPACING_MS);
        Deque<HslGoldenScript.Step> events = new ArrayDeque<>(HslGoldenScript.of(version));
        List<String> differences = new ArrayList<>();
        int packetNumber = 0;
        for (int i = 0; i < DATAGRAMS; i++) {
            while (!events.isEmpty() && events.peek().atMs() <= schedule.next()) {
                HslGoldenScript.Step e = events.poll();
                clock.set(e.atMs());
                game.advance();
                for (String command : e.commands()) {
                    HslGameGoldenTest.perform(game, command, "stream at " + e.atMs() + " ms");
                }
                schedule.changed(e.atMs(), game.controlData().stopped());
            }
            long t = schedule.next();
            clock.set(t);
            byte[] actual = format.encode(game.controlData().withPacketNumber(packetNumber));
            schedule.sent(t, t);
            byte[] expected = Arrays.copyOfRange(stream, i * size, (i + 1) * size);
            String where = "datagram " + i + " (golden at " + times[i][1] + " ms, #" + times[i][2] + "; ours at "
                    + t + " ms, #" + packetNumber + ")";
            if (t != times[i][1] || packetNumber != times[i][2]) {
                differences.add(where + ": send time or packet number");
            }
            HslGameGoldenTest.compare(where, expected, actual, version, differences);
            if (differences.size() >= 10) {
                break;
            }
            packetNumber = (packetNumber + 1) & 0xFF;
        }
        if (!differences.isEmpty()) {
            fail("stream.bin of hsl" + version + " differs (first " + differences.size() + "):\n"
                    + String.join("\n", differences));
        }
    }

    /** Rows of stream-times.csv: index, time_ms, packet_number. */
    private static long[][] times(int version) throws IOException {
        String csv = new String(HslGameGoldenTest.golden(version, "stream-times.csv"), StandardCharsets.US_ASCII);
        return csv.lines().skip(1).filter(l -> !l.isBlank())
                .map(l -> Arrays.stream(l.split(",")).mapToLong(Long::parseLong).toArray())
                .toArray(long[][]::new);
    }
}
