package touchline.transport.gamecontroller;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.game.Game;
import touchline.game.GameClock;
import touchline.game.LeagueParams;
import touchline.game.ToReady;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.GameState7;
import touchline.protocol.gamecontroller.GameState8;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

class GcSenderTest {

    private static Game game() {
        return new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock());
    }

    @Test
    @Tag("integration")
    void sendsOnItsGridWithConsecutivePacketNumbers() throws Exception {
        Game game = game();
        HlGameState12 format = new HlGameState12();
        try (LoopbackReceiver robot = new LoopbackReceiver();
             GcSender sender = new GcSender(p -> game.controlData(), List.of(format), List.of(robot.address()),
                     null, e -> { }, 100, new touchline.app.SystemClock())) {
            sender.start();
            List<LoopbackReceiver.Received> got = new ArrayList<>();
            for (int i = 0; i < 6; i++) {
                LoopbackReceiver.Received r = robot.receive(30_000);
                assertNotNull(r, "packet " + i);
                got.add(r);
            }
            for (int i = 1; i < got.size(); i++) {
                // no packet lost or doubled; when they leave is SendSchedule's (SendScheduleTest, on
                // explicit times) and measured by bench gc, not asserted on this machine's clock here
                assertEquals((got.get(i - 1).data()[6] + 1) & 0xFF, got.get(i).data()[6] & 0xFF, "packetNumber");
            }
        }
    }

    @Test
    @Tag("integration")
    void aStateChangeGoesOutAtOnceNotAtTheNextSlot() throws Exception {
        Game game = game();
        HlGameState12 format = new HlGameState12();
        // an interval far longer than the wait below: a change that waited for its slot would not arrive
        try (LoopbackReceiver robot = new LoopbackReceiver();
             GcSender sender = new GcSender(p -> game.controlData(), List.of(format), List.of(robot.address()),
                     null, e -> { }, 3_600_000, new touchline.app.SystemClock())) {
            game.addListener(sender::sendNow);
            sender.start();
            LoopbackReceiver.Received first = robot.receive(30_000);
            assertNotNull(first, "the first packet goes out at the start");
            assertEquals(GameControlData.STATE_INITIAL, format.decode(first.data()).value().state());
            game.perform(new ToReady());
            LoopbackReceiver.Received r = robot.receive(30_000);
            assertNotNull(r, "the state change was not sent at once (the next slot is an hour away)");
            assertEquals(GameControlData.STATE_READY, format.decode(r.data()).value().state());
            assertEquals((first.data()[6] + 1) & 0xFF, r.data()[6] & 0xFF, "packetNumber");
        }
    }

    @Test
    void packetNumberWrapsFrom255To0AndEveryDatagramIsAnEnvelope() throws Exception {
        Game game = game();
        List<Envelope> envelopes = new CopyOnWriteArrayList<>();
        try (LoopbackReceiver robot = new LoopbackReceiver();
             GcSender sender = new GcSender(p -> game.controlData(), List.of(new GameState8(), new GameState7()),
                     List.of(robot.address()), null, envelopes::add, 1, new touchline.app.SystemClock())) {
            sender.start();
            int[] numbers = new int[300];
            int v7 = 0;
            int v8 = 0;
            while (v8 < numbers.length) {
                LoopbackReceiver.Received r = robot.receive(2000);
                assertNotNull(r);
                if (r.data().length == GameState8.SIZE) {
                    numbers[v8++] = r.data()[5] & 0xFF;
                } else {
                    assertEquals(GameState7.SIZE, r.data().length);
                    v7++;
                }
            }
            assertTrue(v7 >= v8 - 1, "a v7 compatibility packet follows every v8 packet");
            int wrapAt = -1;
            for (int i = 1; i < numbers.length; i++) {
                if (numbers[i] != ((numbers[i - 1] + 1) & 0xFF)) {
                    // the receiver may lose a datagram under load; only the wrap itself matters here
                    continue;
                }
                if (numbers[i - 1] == 255) {
                    wrapAt = i;
                }
            }
            assertEquals(0, numbers[0]);
            assertTrue(wrapAt > 0 && numbers[wrapAt] == 0, "255 is followed by 0: " + Arrays.toString(numbers));
            Await.until(() -> envelopes.size() >= 2 * numbers.length, 2000, "envelopes");
            Envelope e = envelopes.get(0);
            assertEquals(Direction.OUT, e.direction());
            assertEquals(Channel.GAMECONTROLLER, e.channel());
            assertEquals("gc.v8", e.kind());
            assertEquals(robot.address(), e.peer());
            assertEquals("gc.v7", envelopes.get(1).kind());
            assertArrayEquals(new GameState8().encode(game.controlData()), e.raw());
        }
    }
}
