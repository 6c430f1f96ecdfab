package touchline.security;

/**
 * What the console knows of where a datagram came from: {@link #VERIFIED} (a right tag with a
 * new counter from a robot with the team key), {@link #UNVERIFIED} (a console without a key),
 * {@link #UNTAGGED} (no tag while the console has a key: shown, never taken as a command
 * destination), {@link #FORGED} (a wrong, cut or replayed tag, or untagged data claiming a robot
 * that tagged before), and {@link #NOT_CHECKED} for what is not a robot's datagram (outbound,
 * GameController, NAO, recordings made before tags).
 */
public enum Authenticity {
    VERIFIED, UNVERIFIED, UNTAGGED, FORGED, NOT_CHECKED;

    public String word() {
        return name().toLowerCase(java.util.Locale.ROOT).replace('_', ' ');
    }
}
