package touchline.protocol.gamecontroller;

/**
 * Translations between the neutral (HL v12) code space and the 2013/2014 packets, which name
 * the kicking team by colour (2 = dropped ball) and number HL penalties 1..6 instead of 30..35.
 */
final class LegacyCodes {

    static final int DROPBALL_COLOUR = 2;

    private LegacyCodes() {
    }

    static int kickOffColour(GameControlData d) {
        if (d.kickOffTeam() == GameControlData.DROP_BALL) {
            return DROPBALL_COLOUR;
        }
        TeamInfo t = d.team(d.kickOffTeam());
        return t == null ? 0 : t.colour();
    }

    /** Team number of the team wearing {@code colour}, DROP_BALL for 2, or -2 when no team matches. */
    static int kickOffTeam(int colour, int colourA, int numberA, int colourB, int numberB) {
        if (colour == DROPBALL_COLOUR) {
            return GameControlData.DROP_BALL;
        }
        if (colour == colourA) {
            return numberA;
        }
        if (colour == colourB) {
            return numberB;
        }
        return -2;
    }

    static int legacyPenalty(int neutral, boolean humanoid) {
        return humanoid && neutral >= 30 && neutral <= 35 ? neutral - 29 : neutral;
    }

    static int neutralPenalty(int legacy, boolean humanoid) {
        return humanoid && legacy >= 1 && legacy <= 6 ? legacy + 29 : legacy;
    }
}
