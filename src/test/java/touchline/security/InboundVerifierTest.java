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
        InboundVerifier.Result restart = v.check(3, fromRobot(3, 0x0000_0001_0000_0001L));
        assertEquals(Authenticity.VERIFIED, restart.authenticity());
        assertEquals("robot 3 restarted: counter reset, accepted", restart.note());
        byte[] bad = fromRobot(3, 0x0000_0001_0000_0002L);
        bad[bad.length - 1] ^= 1;
        assertEquals("forged: bad tag", v.check(3, bad).reason());
        assertEquals(Authenticity.FORGED, v.check(3, Arrays.copyOf(bad, bad.length - 3)).authenticity());
    }

    @Test
    void untaggedDataIsUnverifiedUntilTheRobotHasTagged() {
        InboundVerifier v = new InboundVerifier(key);
        assertEquals(Authenticity.UNVERIFIED, v.check(5, STATUS).authenticity(), "a robot without a key");
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
