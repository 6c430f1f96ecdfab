package touchline.security;

import java.util.Optional;

/**
 * How the console's link to the small robots is protected: with a team key everything sent is
 * tagged ({@link #tagger}) and every robot datagram checked ({@link #verifier}); {@link #off()}
 * (lab mode, {@code --insecure}) tags nothing and shows everything as unverified.
 */
public final class LinkSecurity {

    private final TeamKey key;
    private final OutboundTagger tagger;
    private final RobotBoots boots;

    private LinkSecurity(TeamKey key, OutboundTagger tagger, RobotBoots boots) {
        this.key = key;
        this.tagger = tagger;
        this.boots = boots;
    }

    public static LinkSecurity off() {
        return new LinkSecurity(null, null, new RobotBoots(RobotBoots.inMemory()));
    }

    /** The key with the robots' boots in memory only (tests, benchmarks). */
    public static LinkSecurity with(TeamKey key, CounterSource counters) {
        return with(key, counters, new RobotBoots(RobotBoots.inMemory()));
    }

    /** The key, the console's counter and the robots' boots (both kept in the key directory). */
    public static LinkSecurity with(TeamKey key, CounterSource counters, RobotBoots boots) {
        return new LinkSecurity(key, new OutboundTagger(key, counters, boots), boots);
    }

    public Optional<TeamKey> key() {
        return Optional.ofNullable(key);
    }

    public Optional<OutboundTagger> tagger() {
        return Optional.ofNullable(tagger);
    }

    /** A new verifier (one per receiving pipeline: it remembers the robots' counters; the boots are shared). */
    public InboundVerifier verifier() {
        return new InboundVerifier(key, boots);
    }

    /** "team key 630dcd29" or "no team key (lab mode)". */
    public String describe() {
        return key == null ? "no team key (lab mode: nothing tagged or checked)" : "team key " + key.idHex()
                + ": commands to robots tagged, robot data checked";
    }
}
