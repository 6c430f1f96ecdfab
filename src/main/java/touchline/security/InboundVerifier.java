package touchline.security;

/**
 * The console's check of the small robots' datagrams: strips the trailer, checks the tag with
 * the team key and the counter with a {@link ReplayGuard}. Without a key every datagram is
 * {@link Authenticity#UNVERIFIED} (a tagged one has its trailer taken off). With a key an untagged
 * robot is {@link Authenticity#UNTAGGED} (shown, never commanded); a robot that has sent verified
 * data is expected to go on tagging: untagged data claiming its id is then forged. Pure; called
 * on the network thread.
 */
public final class InboundVerifier {

    /**
     * @param payloadLength the datagram's length without the trailer (decode only these bytes)
     * @param reason        why it is forged, else null
     * @param note          a remark to show once (a robot's restart), else null
     */
    public record Result(Authenticity authenticity, int payloadLength, String reason, String note) { }

    private final MessageTag tag;
    /** The {@link #precheck}'s own Mac: it runs on another thread than {@link #check} (a Mac is not thread-safe). */
    private final MessageTag pretag;
    private final ReplayGuard guard;
    private final RobotBoots boots;
    private final boolean[] tagged = new boolean[256];

    /**
     * @param key   the team key, or null for a console without one (everything unverified)
     * @param boots the boots believed, shared with the console's tagger
     */
    public InboundVerifier(TeamKey key, RobotBoots boots) {
        this.tag = key == null ? null : new MessageTag(key);
        this.pretag = key == null ? null : new MessageTag(key);
        this.boots = boots;
        this.guard = new ReplayGuard(boots);
    }

    /** A verifier whose boots live in memory only (tests, benchmarks). */
    public InboundVerifier(TeamKey key) {
        this(key, new RobotBoots(RobotBoots.inMemory()));
    }

    public boolean hasKey() {
        return tag != null;
    }

    /** Where the payload ends: robots' datagrams are decoded from these bytes, before {@link #check}. */
    public static int payloadLength(byte[] datagram) {
        return Trailer.of(datagram).payloadLength(datagram.length);
    }

    /** The verdict on a datagram whose payload said it comes from {@code robotId}. */
    public Result check(int robotId, byte[] datagram) {
        return check(robotId, datagram, null);
    }

    /**
     * The tag alone (the HMAC, no counter), for {@link #check(int, byte[], MessageTag.Check)} to
     * finish later: the costly half, which needs no order, so another thread can take it. Null
     * without a key. One thread at a time (its own Mac), beside the thread that calls check.
     */
    public MessageTag.Check precheck(int robotId, byte[] datagram) {
        return pretag == null ? null : pretag.check(MessageTag.FROM_ROBOT, robotId, datagram, Trailer.of(datagram));
    }

    /**
     * The verdict, in arrival order (the counter): {@code prechecked} is what {@link #precheck}
     * said of this datagram, or null to check the tag here too.
     */
    public synchronized Result check(int robotId, byte[] datagram, MessageTag.Check prechecked) {
        Trailer trailer = Trailer.of(datagram);
        int payload = trailer.payloadLength(datagram.length);
        if (tag == null) {
            return new Result(Authenticity.UNVERIFIED, payload, null, null);
        }
        int id = robotId & 0xFF;
        MessageTag.Check c = prechecked != null ? prechecked : tag.check(MessageTag.FROM_ROBOT, robotId, datagram, trailer);
        switch (c) {
            case NO_TAG -> {
                return tagged[id]
                        ? forged(payload, "untagged data claiming robot " + robotId + ", which tags its datagrams")
                        : new Result(Authenticity.UNTAGGED, payload, null, null);
            }
            case TRUNCATED -> {
                return forged(payload, "tag cut short (" + ((Trailer.Truncated) trailer).bytes() + " of 32 trailer bytes)");
            }
            case OUTDATED -> {
                return forged(payload, "tagged with Touchline 0.5's HMAC-SHA-512 trailer (TLA1), which this"
                        + " console no longer checks: flash the robot with this version's firmware (docs/security.md)");
            }
            case WRONG_KEY -> {
                return forged(payload, "tagged with another team key (key-id "
                        + java.util.HexFormat.of().formatHex(datagram, payload + 4, payload + 8) + ", ours "
                        + tag.key().idHex() + ")");
            }
            case BAD_TAG -> {
                return forged(payload, "bad tag");
            }
            default -> { }
        }
        long counter = ((Trailer.Present) trailer).counter();
        int believed = boots.believed(id).orElse(0);
        ReplayGuard.Verdict v = guard.check(robotId, counter);
        if (v == ReplayGuard.Verdict.EARLIER_BOOT) {
            return forged(payload, "from an earlier boot of the robot (boot " + Integer.toUnsignedString((int) (counter >>> 32))
                    + ", the robot runs boot " + Integer.toUnsignedString(believed) + "): an old capture; a robot whose"
                    + " boot number was erased (flash wiped) is taken again after deleting " + KeyDir.BOOTS
                    + " in the key directory");
        }
        if (!v.accepted()) {
            return forged(payload, "replayed or old counter " + Long.toUnsignedString(counter, 16));
        }
        tagged[id] = true;
        return new Result(Authenticity.VERIFIED, payload, null, v.restarted() ? "robot " + robotId
                + " restarted (boot " + Integer.toUnsignedString((int) (counter >>> 32)) + "): counter reset, accepted" : null);
    }

    private static Result forged(int payload, String reason) {
        return new Result(Authenticity.FORGED, payload, "forged: " + reason, null);
    }
}
