package touchline.model;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.SendResult;

import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.*;

class DebugOptionSessionTest {

    private final long[] now = {1_000_000_000L};
    private final List<String> sent = new ArrayList<>();
    private Optional<String> hold = Optional.empty();
    private RobotRegistry registry;
    private DebugOptionSession session;
    private final MessageCodec codec = new MessageCodec(new MessageKinds());

    @BeforeEach
    void setUp() {
        session = new DebugOptionSession((id, m) -> {
            if (hold.isPresent()) {
                return SendResult.held(hold.get());
            }
            sent.add(id + ":" + describe(m));
            return SendResult.sent();
        }, codec, () -> now[0]);
        registry = new RobotRegistry(() -> now[0]);
        registry.addPresenceListener(session);
    }

    private static String describe(Fumanoid.Message m) {
        if (m.hasExtension(Fumanoid.debugOptionListRequest)) {
            return "list?";
        }
        Fumanoid.DebugOptionRequest r = m.getExtension(Fumanoid.debugOptionRequest);
        return (r.getEnable() ? "on " : "off ") + r.getName() + (r.hasMatchRank() ? " #" + r.getMatchRank() : "");
    }

    private void receive(int robot, Fumanoid.Message.Builder m) {
        Fumanoid.Message built = m.setRobotID(robot).build();
        String kind = ((touchline.protocol.MessageResult.Decoded) codec.decode(built.toByteArray())).kind();
        Envelope e = new Envelope(now[0], Direction.IN, Channel.FUMANOID, new InetSocketAddress("127.0.0.1", 4000 + robot),
                robot, kind, built, new byte[10], null);
        registry.live().accept(e);
        session.accept(e);
    }

    private void keepAlive(int robot) {
        receive(robot, Fumanoid.Message.newBuilder().setExtension(Fumanoid.status, Fumanoid.Status.getDefaultInstance()));
    }

    private void list(int robot, String... names) {
        Fumanoid.DebugOptionList.Builder l = Fumanoid.DebugOptionList.newBuilder();
        for (String n : names) {
            l.addOptions(Fumanoid.DebugOption.newBuilder().setName(n).setKind(Fumanoid.DebugKind.TEXT_VALUE));
        }
        receive(robot, Fumanoid.Message.newBuilder().setExtension(Fumanoid.debugOptionList, l.build()));
    }

    /** The robot's list with each option's place in its match digest (0 = none). */
    private void listWithRanks(int robot, String[] names, int[] ranks) {
        Fumanoid.DebugOptionList.Builder l = Fumanoid.DebugOptionList.newBuilder();
        for (int i = 0; i < names.length; i++) {
            l.addOptions(Fumanoid.DebugOption.newBuilder().setName(names[i]).setKind(Fumanoid.DebugKind.PLOT_VALUE)
                    .setMatchRank(ranks[i]));
        }
        receive(robot, Fumanoid.Message.newBuilder().setExtension(Fumanoid.debugOptionList, l.build()));
    }

    @Test
    void matchItemsAreSentHeldDuringPlayAndRetriedUntilTheRobotsListConfirmsThem() {
        keepAlive(3);
        list(3, "a", "b", "c");
        sent.clear();
        hold = Optional.of("match mode, PLAYING");
        SendResult r = session.setMatchItems(3, List.of("c", "a"));
        assertEquals(SendResult.Outcome.HELD, r.outcome(), "never changed during play");
        assertEquals(List.of(), sent);
        assertEquals(1, session.options(3).option("c").orElseThrow().matchRank());
        assertFalse(session.options(3).option("a").orElseThrow().matchConfirmed());

        hold = Optional.empty();
        advance(DebugOptionSession.COMMAND_RETRY_MICROS);
        assertEquals(List.of("3:off a #2", "3:off c #1"), sent, "each place is asked, the option's switch as it is");
        listWithRanks(3, new String[]{"a", "b", "c"}, new int[]{2, 0, 1});
        assertTrue(session.options(3).options().stream().allMatch(OptionState::matchConfirmed));
        sent.clear();
        advance(DebugOptionSession.COMMAND_RETRY_MICROS);
        assertEquals(List.of(), sent, "confirmed: nothing more to send");
        assertEquals(List.of("c", "a"), session.matchItems(3));
        assertEquals(java.util.Map.of(3, List.of("c", "a")), session.allMatchItems());
    }

    @Test
    void matchItemsOfAnEarlierRunGoToTheRobotWhenItsListArrives() {
        session.restoreMatchItems(java.util.Map.of(5, List.of("b")));
        advance(DebugOptionSession.COMMAND_RETRY_MICROS);
        assertEquals(List.of(), sent, "a robot not seen yet is not asked");
        keepAlive(5);
        list(5, "a", "b");
        assertTrue(sent.contains("5:off b #1"), sent.toString());
        assertEquals(List.of("b"), session.matchItems(5));
    }

    @Test
    void aRobotsMatchItemsChosenElsewhereAreLeftAsTheyAre() {
        keepAlive(4);
        listWithRanks(4, new String[]{"a", "b"}, new int[]{0, 1});
        sent.clear();
        advance(DebugOptionSession.COMMAND_RETRY_MICROS);
        assertEquals(List.of(), sent, "another console's choice is not undone");
        assertEquals(1, session.options(4).option("b").orElseThrow().matchRank());
        assertTrue(session.options(4).option("b").orElseThrow().matchConfirmed());
    }

    private void text(int robot, String option) {
        receive(robot, Fumanoid.Message.newBuilder().setExtension(Fumanoid.debugText,
                Fumanoid.DebugText.newBuilder().setOption(option).setText("hi").build()));
    }

    private void advance(long micros) {
        now[0] += micros;
        registry.tick();
        session.tick();
    }

    @Test
    void asksNewRobotForItsListUntilItArrives() {
        keepAlive(3);
        assertEquals(List.of("3:list?"), sent);
        advance(300_000);
        assertEquals(1, sent.size(), "no retry before 500 ms");
        advance(300_000);
        assertEquals(List.of("3:list?", "3:list?"), sent);
        list(3, "demo.text");
        sent.clear();
        advance(600_000);
        assertEquals(List.of(), sent, "no more requests once the list arrived");
        assertTrue(session.options(3).listReceived());
        assertEquals(2, session.options(3).listRequests());
    }

    @Test
    void secondListReplacesFirst() {
        keepAlive(3);
        list(3, "a", "b");
        list(3, "c");
        assertEquals(List.of("c"), session.options(3).options().stream().map(OptionState::name).toList());
    }

    @Test
    void reEnablesWhatWasOnWhenRobotComesBack() {
        keepAlive(3);
        list(3, "demo.text", "demo.plotter");
        session.setWanted(3, "demo.text", true);
        text(3, "demo.text");
        assertTrue(session.options(3).option("demo.text").orElseThrow().streaming());
        sent.clear();

        advance(3_500_000); // keep-alives stop: offline
        assertFalse(registry.robot(3).orElseThrow().online());
        assertTrue(sent.isEmpty(), "nothing is sent to an offline robot");

        keepAlive(3); // back
        assertEquals(List.of("3:list?", "3:on demo.text"), sent);
    }

    @Test
    void retriesWantedOptionUntilDataArrivesAndOffUntilDataStops() {
        keepAlive(3);
        list(3, "demo.text");
        sent.clear();
        session.setWanted(3, "demo.text", true);
        assertEquals(List.of("3:on demo.text"), sent);
        advance(1_000_000);
        keepAlive(3);
        assertEquals(List.of("3:on demo.text", "3:on demo.text"), sent, "retried: no data yet");
        text(3, "demo.text");
        advance(1_000_000);
        assertEquals(2, sent.size(), "data arrived: no more retries");

        session.setWanted(3, "demo.text", false);
        text(3, "demo.text");
        advance(1_000_000);
        assertEquals("3:off demo.text", sent.get(sent.size() - 1));
        long offs = sent.stream().filter(s -> s.equals("3:off demo.text")).count();
        assertEquals(2, offs, "switched off again while data kept coming");
    }

    @Test
    void heldCommandIsReportedAndResumedLater() {
        keepAlive(3);
        list(3, "demo.text");
        hold = Optional.of("match mode: game is PLAYING");
        SendResult r = session.setWanted(3, "demo.text", true);
        assertEquals(SendResult.Outcome.HELD, r.outcome());
        assertEquals("match mode: game is PLAYING", session.options(3).lastHoldReason());
        hold = Optional.empty();
        sent.clear();
        advance(1_000_000);
        keepAlive(3);
        assertEquals(List.of("3:on demo.text"), sent);
        assertEquals("", session.options(3).lastHoldReason());
    }

    /**
     * Notes stale after play (issue 36, item 6): in play the robot sends no option data, so the
     * wanted option's retries were held and the robot's row said "waiting: match mode, game is
     * PLAYING …". After play the robot streams the option again without being asked (it was never
     * switched off): nothing waits any more, and the note goes although no request went out.
     */
    @Test
    void theWaitingNoteGoesWhenNothingWaitsAnyMore() {
        keepAlive(3);
        list(3, "demo.text");
        session.setWanted(3, "demo.text", true);
        text(3, "demo.text");
        hold = Optional.of("match mode, game is PLAYING (this console's GameController); goes out when play stops");
        for (int i = 0; i < 3; i++) { // in play: no data, the retries are held
            advance(1_000_000);
            keepAlive(3);
        }
        assertEquals(hold.get(), session.options(3).lastHoldReason());
        hold = Optional.empty();
        sent.clear();
        text(3, "demo.text"); // play over: the data comes back before the next retry
        advance(100_000);
        assertEquals(List.of(), sent, "streaming again: nothing to send");
        assertEquals("", session.options(3).lastHoldReason());
    }

    @Test
    void unknownKindIsKeptAndNamed() {
        keepAlive(5);
        receive(5, Fumanoid.Message.newBuilder().setExtension(Fumanoid.debugOptionList, Fumanoid.DebugOptionList.newBuilder()
                .addOptions(Fumanoid.DebugOption.newBuilder().setName("team.magic").setKind(77)).build()));
        OptionState o = session.options(5).option("team.magic").orElseThrow();
        assertFalse(o.knownKind());
        assertEquals("unknown kind 77", o.kindName());
    }

    /** Issue #14: a new console wanted nothing and switched off every option another console had on. */
    @Test
    void neverSwitchesOffAnOptionItDidNotSwitchOn() {
        keepAlive(3);
        list(3, "demo.text", "demo.plotter");
        text(3, "demo.text"); // another console of the team switched it on
        sent.clear();
        for (int i = 0; i < 5; i++) {
            advance(1_000_000);
            keepAlive(3);
            text(3, "demo.text");
        }
        assertEquals(List.of(), sent, "the other console's option is left on");
        SendResult r = session.setWanted(3, "demo.text", false);
        assertEquals(SendResult.Outcome.FAILED, r.outcome());
        assertTrue(r.reason().contains("not switched on by this console"), r.reason());
        assertEquals(List.of(), sent, "switching off what it never wanted sends nothing");
    }

    @Test
    void switchingOffIsRetriedAFewTimesOnlyThenLeftToWhoeverWantsIt() {
        keepAlive(3);
        list(3, "demo.text");
        session.setWanted(3, "demo.text", true);
        text(3, "demo.text");
        session.setWanted(3, "demo.text", false);
        for (int i = 0; i < 8; i++) { // another console wants it too: its data keeps coming
            advance(1_000_000);
            keepAlive(3);
            text(3, "demo.text");
        }
        assertEquals(DebugOptionSession.RELEASE_ATTEMPTS, sent.stream().filter(s -> s.equals("3:off demo.text")).count(),
                "switched off a few times, then no fight with the console that wants it");
    }

    @Test
    void restoredWantedOptionsAreSwitchedOnWhenTheRobotAppears() {
        session.restoreWanted(java.util.Map.of(3, java.util.Set.of("demo.plotter")));
        advance(1_000_000);
        assertEquals(List.of(), sent, "nothing goes to a robot not seen yet");
        keepAlive(3);
        list(3, "demo.text", "demo.plotter");
        assertEquals(List.of("3:list?", "3:on demo.plotter"), sent);
        assertTrue(session.options(3).option("demo.plotter").orElseThrow().wanted());
        assertEquals(java.util.Map.of(3, java.util.Set.of("demo.plotter")), session.allWanted());
    }

    @Test
    void restoredWantedOptionsOfARobotAlreadyHereGoOutAtOnce() {
        keepAlive(4);
        list(4, "demo.text");
        sent.clear();
        session.restoreWanted(java.util.Map.of(4, java.util.Set.of("demo.text")));
        assertEquals(List.of("4:on demo.text"), sent);
    }

    /** The options command's --off: the user names the option, so it goes off whoever switched it on. */
    @Test
    void anOptionTheUserNamesIsSwitchedOffWhoeverSwitchedItOn() {
        keepAlive(3);
        list(3, "demo.text");
        text(3, "demo.text"); // another console's
        sent.clear();
        assertTrue(session.switchOff(3, "demo.text").isSent());
        assertEquals(List.of("3:off demo.text"), sent);
        text(3, "demo.text"); // one more on its way
        advance(1_000_000);
        keepAlive(3);
        assertEquals(List.of("3:off demo.text", "3:off demo.text"), sent, "data still came: tried again");
        advance(1_100_000);
        keepAlive(3);
        advance(1_000_000);
        keepAlive(3);
        assertEquals(2, sent.size(), "the data stopped: nothing more to switch off");
        assertFalse(session.options(3).option("demo.text").orElseThrow().wanted());
    }

    @Test
    void theTickDoesNotAskAgainWhileTheFirstListRequestIsOnItsWay() {
        // the request is published on the UDP stage's thread while the tick runs on its own:
        // here the tick runs from inside the send, i.e. while the first request is on its way
        List<String> requests = new ArrayList<>();
        DebugOptionSession[] self = new DebugOptionSession[1];
        self[0] = new DebugOptionSession((id, m) -> {
            requests.add(id + ":" + describe(m));
            if (requests.size() == 1) {
                now[0] += DebugOptionSession.LIST_RETRY_MICROS - 1; // slow, but not yet due for a retry
                self[0].tick();
            }
            return SendResult.sent();
        }, codec, () -> now[0]);
        self[0].cameOnline(4, true);
        assertEquals(List.of("4:list?"), requests, "one list request, not a second one from the tick");
        now[0] += DebugOptionSession.LIST_RETRY_MICROS;
        self[0].tick();
        assertEquals(List.of("4:list?", "4:list?"), requests, "retried when due");
    }
}
