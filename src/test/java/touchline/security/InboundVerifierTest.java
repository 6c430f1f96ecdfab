package touchline.security;

import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.*;

class InboundVerifierTest {

    private final TeamKey key = MessageTagTest.goldenKey();
    private final MessageTag robotSide = new MessageTag(key);
    private static final byte[] STATUS = "status of robot 3".getBytes(StandardCharsets.US_ASCII);

    private byte[] fromRobot(int robot, long counter) {
        return robotSide.append(MessageTag.FROM_ROBOT, robot, counter, STATUS);
    }

    @Test
    void verifiedThenReplayedThenRestartedThenForged() {
        InboundVerifier v = new InboundVerifier(key);
        InboundVerifier.Result ok = v.check(3, fromRobot(3, 0x0000_0007_0000_0001L));
        assertEquals(Authenticity.VERIFIED, ok.authenticity());
        assertEquals(STATUS.length, ok.payloadLength());
        InboundVerifier.Result replay = v.check(3, fromRobot(3, 0x0000_0007_0000_0001L));
        assertEquals(Authenticity.FORGED, replay.authenticity());
        assertTrue(replay.reason().contains("replayed"), replay.reason());
        InboundVerifier.Result restart = v.check(3, fromRobot(3, 0x0000_0008_0000_0001L));
        assertEquals(Authenticity.VERIFIED, restart.authenticity());
        assertEquals("robot 3 restarted (boot 8): counter reset, accepted", restart.note());
        byte[] bad = fromRobot(3, 0x0000_0008_0000_0002L);
        bad[bad.length - 1] ^= 1;
        assertEquals("forged: bad tag", v.check(3, bad).reason());
        assertEquals(Authenticity.FORGED, v.check(3, Arrays.copyOf(bad, bad.length - 3)).authenticity());
    }

    /**
     * Issue 35: captures of the robot's earlier boot, played after the console verified its
     * current one, are refused and change nothing: the robot's current datagrams still pass.
     */
    @Test
    void capturesOfAnEarlierBootNeverDisplaceTheCurrentBoot() {
        InboundVerifier v = new InboundVerifier(key);
        assertEquals(Authenticity.VERIFIED, v.check(3, fromRobot(3, 0x0000_0008_0000_0001L)).authenticity());
        for (int seq = 1; seq <= 3; seq++) {
            InboundVerifier.Result old = v.check(3, fromRobot(3, 0x0000_0007_0000_0100L + seq));
            assertEquals(Authenticity.FORGED, old.authenticity());
            assertTrue(old.reason().contains("earlier boot"), old.reason());
        }
        assertEquals(Authenticity.VERIFIED, v.check(3, fromRobot(3, 0x0000_0008_0000_0002L)).authenticity(),
                "the robot's current boot is still believed");
    }

    /** The boots believed outlive the console: a console started after the capture refuses it too. */
    @Test
    void aConsoleStartedLaterStillKnowsTheRobotsBoot(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) {
        KeyDir keys = new KeyDir(dir);
        new InboundVerifier(key, new RobotBoots(keys.bootStore())).check(3, fromRobot(3, 0x0000_0008_0000_0005L));
        InboundVerifier later = new InboundVerifier(key, new RobotBoots(new KeyDir(dir).bootStore()));
        assertEquals(Authenticity.FORGED, later.check(3, fromRobot(3, 0x0000_0007_0000_0009L)).authenticity());
        assertEquals(Authenticity.VERIFIED, later.check(3, fromRobot(3, 0x0000_0008_0000_0006L)).authenticity());
    }

    /**
     * The HMAC checked ahead on another thread (the event loop, while the publishing thread is
     * behind) and the counter settled later, in order: the same verdicts as one check, and a tag
     * found right does not let a replayed counter through.
     */
    @Test
    void aTagCheckedAheadGivesTheSameVerdictAndTheCounterIsStillSettledInOrder() {
        InboundVerifier v = new InboundVerifier(key);
        byte[] first = fromRobot(3, 0x0000_0007_0000_0001L);
        byte[] second = fromRobot(3, 0x0000_0007_0000_0002L);
        MessageTag.Check firstTag = v.precheck(3, first);
        MessageTag.Check secondTag = v.precheck(3, second);
        MessageTag.Check replayTag = v.precheck(3, first);
        assertEquals(MessageTag.Check.OK, firstTag);
        assertEquals(Authenticity.VERIFIED, v.check(3, first, firstTag).authenticity());
        assertEquals(Authenticity.VERIFIED, v.check(3, second, secondTag).authenticity());
        InboundVerifier.Result replay = v.check(3, first, replayTag);
        assertEquals(Authenticity.FORGED, replay.authenticity(), "a right tag, an old counter");
        assertTrue(replay.reason().contains("replayed"), replay.reason());

        byte[] bad = fromRobot(3, 0x0000_0007_0000_0003L);
        bad[bad.length - 1] ^= 1;
        MessageTag.Check badTag = v.precheck(3, bad);
        assertEquals(MessageTag.Check.BAD_TAG, badTag);
        assertEquals("forged: bad tag", v.check(3, bad, badTag).reason());
        assertEquals(Authenticity.VERIFIED, v.check(3, fromRobot(3, 0x0000_0007_0000_0003L)).authenticity(),
                "the forgery's counter was not taken");
        assertEquals(MessageTag.Check.NO_TAG, v.precheck(3, STATUS));
        assertEquals(Authenticity.FORGED, v.check(3, STATUS, MessageTag.Check.NO_TAG).authenticity(),
                "robot 3 tags: untagged data in its name is forged");
        assertNull(new InboundVerifier(null).precheck(3, first), "nothing to check without a key");
    }

    /** A robot still on Touchline 0.5's firmware (trailer "TLA1", HMAC-SHA-512): told to update, its data not taken. */
    @Test
    void aVersionOneTrailerIsForgedWithKeyAndStrippedWithout() {
        byte[] v1 = fromRobot(3, 1);
        v1[STATUS.length + 3] = '1'; // the same bytes behind 0.5's magic
        InboundVerifier.Result keyed = new InboundVerifier(key).check(3, v1);
        assertEquals(Authenticity.FORGED, keyed.authenticity());
        assertTrue(keyed.reason().contains("TLA1") && keyed.reason().contains("firmware"), keyed.reason());
        assertEquals(STATUS.length, keyed.payloadLength());
        InboundVerifier.Result lab = new InboundVerifier(null).check(3, v1);
        assertEquals(Authenticity.UNVERIFIED, lab.authenticity());
        assertEquals(STATUS.length, lab.payloadLength(), "without a key the payload is decoded without the trailer");
    }

    @Test
    void untaggedDataIsUntaggedUntilTheRobotHasTagged() {
        InboundVerifier v = new InboundVerifier(key);
        assertEquals(Authenticity.UNTAGGED, v.check(5, STATUS).authenticity(), "a robot without a key");
        assertEquals(Authenticity.VERIFIED, v.check(3, fromRobot(3, 1)).authenticity());
        InboundVerifier.Result spoof = v.check(3, STATUS);
        assertEquals(Authenticity.FORGED, spoof.authenticity(), "robot 3 tags: untagged data in its name is forged");
        assertTrue(spoof.reason().contains("untagged"), spoof.reason());
    }

    @Test
    void wrongKeyIsNamedByKeyId() {
        byte[] other = new byte[32];
        other[31] = 9;
        TeamKey otherKey = new TeamKey(other);
        byte[] foreign = new MessageTag(otherKey).append(MessageTag.FROM_ROBOT, 3, 1, STATUS);
        InboundVerifier.Result r = new InboundVerifier(key).check(3, foreign);
        assertEquals(Authenticity.FORGED, r.authenticity());
        assertTrue(r.reason().contains(otherKey.idHex()) && r.reason().contains(key.idHex()), r.reason());
    }

    @Test
    void withoutAKeyEverythingIsUnverifiedAndTheTrailerIsTakenOff() {
        InboundVerifier v = new InboundVerifier(null);
        InboundVerifier.Result r = v.check(3, fromRobot(3, 1));
        assertEquals(Authenticity.UNVERIFIED, r.authenticity());
        assertEquals(STATUS.length, r.payloadLength());
    }
}
