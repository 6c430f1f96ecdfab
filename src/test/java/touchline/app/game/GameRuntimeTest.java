package touchline.app.game;

import org.junit.jupiter.api.Test;
import touchline.app.SystemClock;
import touchline.game.Game;
import touchline.game.LeagueAction;
import touchline.game.LeagueParams;
import touchline.game.ManualClock;
import touchline.game.Outcome;
import touchline.game.Penalize;
import touchline.game.Penalty;
import touchline.game.ToPlaying;
import touchline.game.ToReady;
import touchline.game.ToSet;
import touchline.game.hsl.Competition;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslRules;
import touchline.game.hsl.FreeSetPlay;
import touchline.game.hsl.HslStartSetPlay;
import touchline.game.hsl.SetPlay;
import touchline.game.hsl.StopPlay;
import touchline.game.hsl.WaitForSetPlay;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.protocol.gamecontroller.HslGameState20;
import touchline.protocol.gamecontroller.TeamColour;
import touchline.testing.Await;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;

import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** One owner thread changes the game; faces and the sender only enqueue and read snapshots. */
class GameRuntimeTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);

    private static Game game(touchline.game.GameClock clock) {
        return new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, clock);
    }

    @Test
    void actionsFromSeveralThreadsAreAppliedByTheOwnerInTheOrderTheyCame() throws Exception {
        Game game = game(new ManualClock(0));
        Set<String> changedOn = ConcurrentHashMap.newKeySet();
        List<String> enqueued = new ArrayList<>();
        List<CompletableFuture<Outcome>> outcomes = new CopyOnWriteArrayList<>();
        try (GameRuntime owner = new GameRuntime(game)) {
            game.addListener(() -> changedOn.add(Thread.currentThread().getName()));
            CountDownLatch go = new CountDownLatch(1);
            List<Thread> faces = new ArrayList<>();
            for (int team : new int[]{13, 7}) {
                Thread face = new Thread(() -> {
                    try {
                        go.await();
                    } catch (InterruptedException e) {
                        return;
                    }
                    for (int player = 1; player <= 4; player++) {
                        Penalize p = new Penalize(team, player, Penalty.PHYSICAL_CONTACT);
                        synchronized (enqueued) { // the order of enqueueing, across both faces
                            enqueued.add(p.describe());
                            outcomes.add(owner.perform(p));
                        }
                    }
                }, "face-" + team);
                faces.add(face);
                face.start();
            }
            owner.start();
            go.countDown();
            for (Thread face : faces) {
                face.join();
            }
            for (CompletableFuture<Outcome> o : outcomes) {
                assertTrue(o.join().applied(), o.join().message());
            }
            List<String> applied = new ArrayList<>(owner.snapshot().undoList());
            java.util.Collections.reverse(applied);
            assertEquals(enqueued, applied, "applied in the order enqueued");
            assertEquals(Set.of(GameRuntime.THREAD), changedOn, "only the owner changed the game");
        }
    }

    @Test
    void theSenderReadsSnapshotsAndTimeIsAnEventOfTheOwner() throws Exception {
        ManualClock clock = new ManualClock(0);
        Game game = game(clock);
        Set<String> changedOn = ConcurrentHashMap.newKeySet();
        game.addListener(() -> changedOn.add(Thread.currentThread().getName()));
        try (DatagramSocket robot = new DatagramSocket(ANY_LOOPBACK_PORT);
             EmbeddedGameController gc = new EmbeddedGameController(game, new GcConfig(GcProfile.HL12, false,
                     List.of((InetSocketAddress) robot.getLocalSocketAddress()), ANY_LOOPBACK_PORT, ANY_LOOPBACK_PORT,
                     null, 10, false), e -> { }, null, new SystemClock())) {
            gc.start();
            assertTrue(gc.runtime().perform(new Penalize(13, 1, Penalty.PHYSICAL_CONTACT)).join().applied());
            clock.advance(10 * 60_000); // the penalty ends at the owner's next timer event (the sender's cycle)
            Await.until("the penalty ended by time",
                    () -> gc.runtime().snapshot().hl().team(13).player(1).penalty() == Penalty.NONE);
            long sent = gc.packetsSent();
            Await.until("the sender goes on", () -> gc.packetsSent() > sent + 2);
            assertEquals(Set.of(GameRuntime.THREAD), changedOn,
                    "the game changed on the owner only, never inside the sender's supplier");
        }
    }

    @Test
    void eventsWaitForTheStartAndAreRefusedAfterTheClose() {
        Game game = game(new ManualClock(0));
        GameRuntime owner = new GameRuntime(game);
        CompletableFuture<Outcome> early = owner.perform(new ToReady());
        assertFalse(early.isDone(), "nothing runs before the owner starts");
        owner.start();
        assertTrue(early.join().applied());
        owner.close();
        Outcome late = owner.perform(new Penalize(13, 1, Penalty.PHYSICAL_CONTACT)).join();
        assertFalse(late.applied());
        assertEquals("the GameController is stopped", late.message());
    }

    @Test
    void anActionOfAnotherLeagueIsRefusedWithTheReason() {
        HslGame hsl = new HslGame(HslRules.v7(Competition.MIDDLE_ADVANCED), 5,
                new TeamColour[]{TeamColour.RED, TeamColour.PURPLE}, 14,
                new TeamColour[]{TeamColour.BLUE, TeamColour.YELLOW}, new ManualClock(0));
        try (GameRuntime owner = new GameRuntime(hsl)) {
            owner.start();
            Outcome o = owner.perform(new ToReady()).join();
            assertFalse(o.applied());
            assertEquals("ready is not an action of this game's rules", o.message());
        }
    }

    @Test
    void aSnapshotRunOnToAnInstantIsWhatTheOwnersTimerMakesOfIt() {
        ManualClock clock = new ManualClock(0);
        try (GameRuntime owner = new GameRuntime(game(clock))) {
            owner.start();
            for (LeagueAction<?> a : List.<LeagueAction<?>>of(new ToReady(), new ToSet(), new ToPlaying(),
                    new Penalize(13, 1, Penalty.PHYSICAL_CONTACT))) {
                assertTrue(owner.perform(a).join().applied());
            }
            sameAsTheOwnersTimer(owner, clock, new HlGameState12(), new HlGameState12());
        }
        ManualClock hslClock = new ManualClock(0);
        try (GameRuntime owner = new GameRuntime(new HslGame(HslRules.v7(Competition.MIDDLE_ADVANCED), 5,
                new TeamColour[]{TeamColour.RED, TeamColour.PURPLE}, 14,
                new TeamColour[]{TeamColour.BLUE, TeamColour.YELLOW}, hslClock))) {
            owner.start();
            for (LeagueAction<?> a : List.<LeagueAction<?>>of(new HslStartSetPlay(5, SetPlay.KICK_OFF),
                    new WaitForSetPlay(), new FreeSetPlay(), new StopPlay(false))) {
                assertTrue(owner.perform(a).join().applied());
            }
            sameAsTheOwnersTimer(owner, hslClock, new HslGameState20(), HslGameState20.trueData());
        }
    }

    /** Through penalties ending, set plays timing out and halves ending: the sender's view equals the owner's, byte for byte. */
    private static void sameAsTheOwnersTimer(GameRuntime owner, ManualClock clock, GameStateFormat robots,
                                             GameStateFormat truth) {
        for (int step = 0; step < 200; step++) {
            RefereeSnapshot before = owner.snapshot();
            clock.advance(7_300);
            RefereeSnapshot sent = before.at(clock.millis());
            RefereeSnapshot owners = owner.tick().join();
            assertArrayEquals(robots.encode(owners.robots()), robots.encode(sent.robots()), "robots at step " + step);
            assertArrayEquals(truth.encode(owners.truth()), truth.encode(sent.truth()), "truth at step " + step);
            assertEquals(owners.description(), sent.description(), "step " + step);
        }
    }

    @Test
    void theSendersTimerTakesNoLockTheOwnerHolds() throws Exception {
        try (GameRuntime owner = new GameRuntime(game(new ManualClock(0)))) {
            owner.start();
            CompletableFuture<RefereeSnapshot> timed = new CompletableFuture<>();
            synchronized (owner) { // as the owner holds it taking its next event, then is not scheduled
                new Thread(() -> timed.complete(owner.timed()), "gc-sender").start();
                Await.until("the sender's timer while the owner holds its queue", timed::isDone);
            }
        }
    }
}
