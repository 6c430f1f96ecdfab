package touchline.ui.referee;

import touchline.game.hsl.Competition;
import touchline.protocol.gamecontroller.MonitorRequest;
import touchline.protocol.gamecontroller.TeamColour;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;

/**
 * What the GameController tab's form says: the texts as typed (checked when the game starts) and
 * what is chosen. The HSL values (competition, each team's field player and goalkeeper colour, the
 * monitors' port) are kept for the older formats too, which do not use them.
 *
 * @param format       a {@link GcProfile}'s CLI name, e.g. {@code hsl20}
 * @param teamA        team A's number (left, kicks off)
 * @param destinations {@code host:port} list, comma separated
 * @param returnPort   the return packets' port; blank for the format's default
 * @param realtime     ask for real-time priority for the sender
 * @param monitorPort  where HSL monitors register; blank for none
 */
record GameSetup(String format, String teamA, String teamB, String destinations, String returnPort, boolean realtime,
                 Competition competition, TeamColour fieldA, TeamColour keeperA, TeamColour fieldB,
                 TeamColour keeperB, String monitorPort) {

    /** The formats' CLI names, in {@link GcProfile}'s order (the form's choices). */
    static final java.util.List<String> FORMATS = java.util.Arrays.stream(GcProfile.values())
            .map(GcProfile::cliName).toList();

    /** Default destinations, e.g. the demo team's robot ports; else the official broadcast. */
    static final String DESTINATIONS_PROPERTY = "touchline.gc.dest";

    /**
     * The form before anything is remembered: HSL 2026 first (GcProfile lists hsl20 first, the
     * official GameController's format since RoboCup 2026), teams 13 and 7, the official
     * launcher's colours, real-time priority on (a crowded laptop must not move the 500 ms cadence).
     */
    static GameSetup defaults() {
        return new GameSetup(FORMATS.get(0), "13", "7",
                System.getProperty(DESTINATIONS_PROPERTY, GcConfig.DEFAULT_BROADCAST + ":" + GcProfile.GAME_STATE_PORT),
                "", true, Competition.MIDDLE_ADVANCED, TeamColour.RED, TeamColour.PURPLE, TeamColour.BLUE,
                TeamColour.YELLOW, Integer.toString(MonitorRequest.PORT));
    }

    /** The chosen format, or null when the text names none. */
    GcProfile profile() {
        return profile(format);
    }

    /** The format {@code name} names, or null. */
    static GcProfile profile(String name) {
        return name == null ? null : GcProfile.parse(name);
    }

    TeamColour[] coloursA() {
        return new TeamColour[]{fieldA, keeperA};
    }

    TeamColour[] coloursB() {
        return new TeamColour[]{fieldB, keeperB};
    }
}
