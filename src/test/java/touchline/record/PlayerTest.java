package touchline.record;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.testing.Await;
import touchline.transport.Envelope;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Player semantics against a clock the test advances by hand: no sleeping. */
class PlayerTest {

    @TempDir
    Path dir;

    private final AtomicLong now = new AtomicLong(1_000_000_000L);
    private final List<Envelope> got = new CopyOnWriteArrayList<>();
    private List<Envelope> sent;
    /** How many envelopes had been delivered at each jump. */
    private final List<Integer> jumps = new CopyOnWriteArrayList<>();
    private Recording recording;
    private Player player;

    @BeforeEach
    void open() throws Exception {
        sent = RecordingFixture.team(3, 60);
        Path file = dir.resolve("p.mcap");
        RecordingFixture.write(file, sent, new EnvelopeWriter.Options(0, 0, 16 * 1024, List.of()));
        sent = sent.stream().map(Envelope::asReplayed).toList(); // what a player delivers is marked as replayed
        recording = Recording.open(file);
        player = new Player(recording, got::add, now::get, () -> jumps.add(got.size()));
    }

    @AfterEach
    void close() {
        player.close();
        recording.close();
    }

    private void advanceMillis(long ms) {
        now.addAndGet(ms * 1_000_000L);
        player.pump();
    }

    private List<Envelope> sentUpTo(long micros) {
        return sent.stream().filter(e -> e.timeMicros() <= micros).toList();
    }

    @Test
    void playsInRealTimeAndPauseStopsTheClock() {
        long start = recording.startMicros();
        assertEquals(RecordingFixture.START + 17, start);
        player.play();
        advanceMillis(2_000);
        assertEquals(sentUpTo(start + 2_000_000), got);
        assertEquals(start + 2_000_000, player.snapshot().positionMicros());

        player.pause();
        advanceMillis(10_000);
        assertEquals(sentUpTo(start + 2_000_000), got, "nothing while paused");
        assertFalse(player.snapshot().playing());

        player.play();
        advanceMillis(1_000);
        assertEquals(sentUpTo(start + 3_000_000), got);
    }

    @Test
    void speedScalesRecordingTimePerWallTimeAndIsClamped() {
        long start = recording.startMicros();
        assertEquals(10, player.setSpeed(10));
        player.play();
        advanceMillis(500);
        assertEquals(sentUpTo(start + 5_000_000), got);
        assertEquals(0.1, player.setSpeed(0.01));
        advanceMillis(1_000);
        assertEquals(sentUpTo(start + 5_100_000), got);
        assertEquals(50, player.setSpeed(400));
        assertEquals(50, player.snapshot().speed());
    }

    @Test
    void seekLandsOnTheRightTimeAndPlaysOnFromThere() {
        long target = recording.startMicros() + 30_000_000L;
        player.seek(target);
        assertEquals(target, player.snapshot().positionMicros());
        assertEquals(List.of(0), jumps, "the jump is announced before anything plays from there");
        player.pump();
        int state = got.size(); // the state at the play head (aSeekWhilePaused…)
        player.play();
        advanceMillis(1_000);
        List<Envelope> expected = sent.stream()
                .filter(e -> e.timeMicros() > target && e.timeMicros() <= target + 1_000_000).toList();
        assertEquals(expected, got.subList(state, got.size()));
        assertTrue(got.get(state).timeMicros() - target < 100_000, "the first envelope after the seek is right there");

        got.clear();
        player.seek(recording.startMicros() - 5_000_000L);
        assertEquals(recording.startMicros(), player.snapshot().positionMicros(), "clamped to the start");
    }

    /** The newest envelope of each direction, channel, robot and kind up to {@code micros}, oldest first. */
    private List<Envelope> newestOfEachKindUpTo(long micros) {
        java.util.Map<List<Object>, Envelope> newest = new java.util.LinkedHashMap<>();
        for (Envelope e : sentUpTo(micros)) {
            List<Object> key = List.of(e.direction(), e.channel(), e.robotId(), e.kind());
            newest.remove(key);
            newest.put(key, e);
        }
        return List.copyOf(newest.values());
    }

    /**
     * Issue 36 item 5: a seek while paused shows the state at the play head: the newest envelope of
     * each robot and kind at or before it is delivered once, and playing goes on after it.
     */
    @Test
    void aSeekWhilePausedDeliversTheNewestOfEachRobotAndKindAtThePlayHead() {
        long target = recording.startMicros() + 30_000_000L + 123;
        player.seek(target);
        advanceMillis(1_000);
        List<Envelope> state = newestOfEachKindUpTo(target);
        assertTrue(state.stream().map(Envelope::robotId).distinct().count() >= 3, "every robot of the team: " + state);
        assertEquals(state, got);
        assertEquals(state.size(), player.snapshot().emitted(), "counted as delivered");
        advanceMillis(1_000);
        assertEquals(state, got, "once");

        player.seek(target + 5_000_000L); // again, further on: that state, afresh
        advanceMillis(1_000);
        assertEquals(List.of(0, state.size()), jumps);
        assertEquals(newestOfEachKindUpTo(target + 5_000_000L), got.subList(state.size(), got.size()));

        got.clear();
        player.play();
        advanceMillis(1_000);
        assertEquals(sent.stream().filter(e -> e.timeMicros() > target + 5_000_000L
                && e.timeMicros() <= target + 6_000_000L).toList(), got, "then it plays on from the play head");
    }

    @Test
    void findsGoalStateChangesAndALostRobotAndSeeksToThem() {
        List<TimelineEvent> events = player.events();
        List<TimelineEvent.Type> types = new ArrayList<>(events.stream().map(TimelineEvent::type).toList());
        assertTrue(types.contains(TimelineEvent.Type.GOAL), events.toString());
        assertEquals(4, types.stream().filter(t -> t == TimelineEvent.Type.STATE_CHANGE).count(), events.toString());
        TimelineEvent lost = events.stream().filter(e -> e.type() == TimelineEvent.Type.ROBOT_LOST).findFirst().orElseThrow();
        assertEquals(2, lost.robotId());

        TimelineEvent goal = player.seekToNext(TimelineEvent.Type.GOAL).orElseThrow();
        assertEquals(RecordingFixture.START + 40_000_000L + 17, goal.timeMicros(), "the first packet with the new score");
        assertTrue(goal.label().contains("1:0"), goal.label());
        assertEquals(goal.timeMicros(), player.snapshot().positionMicros());
        assertTrue(player.seekToNext(TimelineEvent.Type.GOAL).isEmpty());
    }

    @Test
    void loopsARangeAndFinishesAtTheEndOtherwise() {
        long from = recording.startMicros() + 10_000_000L;
        long to = from + 2_000_000L;
        player.setLoop(from, to);
        player.setSpeed(50);
        player.play();
        advanceMillis(100); // 5 s of recording: two and a half laps
        assertTrue(got.stream().allMatch(e -> e.timeMicros() >= from && e.timeMicros() <= to));
        long firstLap = sent.stream().filter(e -> e.timeMicros() >= from && e.timeMicros() <= to).count();
        assertTrue(got.size() > 2 * firstLap, got.size() + " vs a lap of " + firstLap);
        assertTrue(jumps.size() >= 3, "into the range, then each lap going round: " + jumps);

        player.clearLoop();
        got.clear();
        advanceMillis(10_000);
        assertTrue(player.snapshot().finished());
        assertEquals(recording.endMicros(), player.snapshot().positionMicros());
        assertEquals(sent.get(sent.size() - 1), got.get(got.size() - 1));
    }

    @Test
    void headlessRunDeliversEverythingInOrder() {
        assertEquals(sent.size(), player.runToEnd());
        assertEquals(sent, got);
        assertTrue(got.stream().allMatch(Envelope::replayed), "every envelope a player delivers is marked");
        assertTrue(player.snapshot().finished());
        assertEquals(List.of(), jumps, "playing straight through never jumps");
    }

    @Test
    void seekingBackAnnouncesTheJumpBeforeTheEarlierEnvelopesPlayAgain() {
        player.play();
        advanceMillis(3_000);
        int before = got.size();
        player.seek(recording.startMicros());
        assertEquals(List.of(before), jumps);
        advanceMillis(1_000);
        assertEquals(sentUpTo(recording.startMicros() + 1_000_000), got.subList(before, got.size()),
                "after the jump it plays as if from the start");
    }

    @Test
    void theDeliveryThreadPlaysWithoutPumping() throws Exception {
        CountDownLatch hundred = new CountDownLatch(100);
        Player threaded = new Player(recording, e -> {
            got.add(e);
            hundred.countDown();
        }, new touchline.app.SystemClock());
        try {
            threaded.setSpeed(50);
            threaded.start();
            threaded.play();
            assertTrue(hundred.await(Await.FLOOR_MILLIS, TimeUnit.MILLISECONDS),
                    "the delivery thread delivered 100 envelopes, no one pumping (" + got.size() + " so far)");
            assertEquals(sent.subList(0, 100), List.copyOf(got).subList(0, 100)); // a copy: the player thread goes on adding
        } finally {
            threaded.close();
        }
    }

    /**
     * Issue 38: the player delivers outside its lock. While a subscriber is held inside a
     * delivery, speed, pause and seek return without waiting for it; the seek's jump is announced
     * when that delivery ends, nothing else of the batch from before the seek follows it, and the
     * state at the new play head comes next.
     */
    @Test
    void aControlWhileASubscriberIsHeldInsideADeliveryReturnsWithoutWaitingForIt() throws Exception {
        CountDownLatch inside = new CountDownLatch(1);
        CountDownLatch release = new CountDownLatch(1);
        List<Envelope> held = new CopyOnWriteArrayList<>();
        List<Integer> heldJumps = new CopyOnWriteArrayList<>();
        Player p = new Player(recording, e -> {
            held.add(e);
            if (held.size() == 1) {
                inside.countDown();
                try {
                    release.await();
                } catch (InterruptedException interrupted) {
                    Thread.currentThread().interrupt();
                }
            }
        }, now::get, () -> heldJumps.add(held.size()));
        java.util.concurrent.ExecutorService delivering = java.util.concurrent.Executors.newSingleThreadExecutor();
        java.util.concurrent.ExecutorService controlling = java.util.concurrent.Executors.newSingleThreadExecutor();
        long target = recording.startMicros() + 30_000_000L;
        try {
            p.play();
            now.addAndGet(2_000_000_000L); // two seconds of envelopes due: one batch
            java.util.concurrent.Future<Long> pumping = delivering.submit(p::pump);
            assertTrue(inside.await(Await.FLOOR_MILLIS, TimeUnit.MILLISECONDS), "the subscriber holds the first envelope");
            java.util.concurrent.Future<?> controls = controlling.submit(() -> {
                p.setSpeed(2);
                p.pause();
                p.seek(target);
            });
            try {
                controls.get(Await.FLOOR_MILLIS, TimeUnit.MILLISECONDS);
            } catch (java.util.concurrent.TimeoutException waited) {
                throw new AssertionError("a control waited for the subscriber held inside a delivery", waited);
            }
            assertEquals(List.of(), heldJumps, "the jump waits for the delivery in hand");
            assertEquals(target, p.snapshot().positionMicros());

            release.countDown();
            pumping.get(Await.FLOOR_MILLIS, TimeUnit.MILLISECONDS);
            assertEquals(List.of(1), heldJumps, "announced when that delivery ended");
            assertEquals(1, held.size(), "nothing of the batch from before the seek after the jump");
            p.pump();
            assertEquals(newestOfEachKindUpTo(target), held.subList(1, held.size()), "then the state at the play head");
        } finally {
            release.countDown();
            p.close();
            delivering.shutdownNow();
            controlling.shutdownNow();
        }
    }
}
