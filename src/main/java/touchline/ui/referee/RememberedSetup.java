package touchline.ui.referee;

import touchline.game.hsl.Competition;
import touchline.protocol.gamecontroller.TeamColour;
import touchline.ui.window.SettingsFile;

import java.nio.file.Path;
import java.util.Properties;

/**
 * The GameController tab's last setup (format, teams, destinations, return port, HSL
 * competition and colours), remembered in {@code gamecontroller.properties} beside the
 * layouts and the window places ({@link SettingsFile}), written when a game starts. Without
 * a settings directory nothing is remembered.
 */
final class RememberedSetup {

    private final SettingsFile file;

    RememberedSetup(Path settingsDir) {
        this.file = settingsDir == null ? null
                : new SettingsFile(settingsDir.resolve("gamecontroller.properties"), "the GameController setup");
    }

    /**
     * {@code shown} with what was remembered; a value that no longer names anything (edited by
     * hand, from another release) keeps what is shown. Destinations given by
     * {@value GameSetup#DESTINATIONS_PROPERTY} (the demo names its robots' ports) win over the
     * ones typed last time.
     */
    GameSetup restore(GameSetup shown) {
        Properties p = file == null ? new Properties() : file.read();
        if (p.isEmpty()) {
            return shown;
        }
        String format = p.getProperty("format");
        String destinations = System.getProperty(GameSetup.DESTINATIONS_PROPERTY) == null
                ? p.getProperty("destinations", shown.destinations()) : shown.destinations();
        return new GameSetup(GameSetup.FORMATS.contains(format) ? format : shown.format(),
                p.getProperty("teamA", shown.teamA()), p.getProperty("teamB", shown.teamB()), destinations,
                p.getProperty("returnPort", shown.returnPort()), shown.realtime(),
                named(Competition.class, p.getProperty("competition"), shown.competition()),
                named(TeamColour.class, p.getProperty("colourA"), shown.fieldA()),
                named(TeamColour.class, p.getProperty("goalkeeperColourA"), shown.keeperA()),
                named(TeamColour.class, p.getProperty("colourB"), shown.fieldB()),
                named(TeamColour.class, p.getProperty("goalkeeperColourB"), shown.keeperB()),
                p.getProperty("monitorPort", shown.monitorPort()));
    }

    private static <E extends Enum<E>> E named(Class<E> type, String name, E shown) {
        if (name == null) {
            return shown;
        }
        try {
            return Enum.valueOf(type, name);
        } catch (IllegalArgumentException e) {
            return shown;
        }
    }

    void save(GameSetup setup) {
        if (file == null) {
            return;
        }
        Properties p = new Properties();
        p.setProperty("format", setup.format());
        p.setProperty("teamA", setup.teamA().strip());
        p.setProperty("teamB", setup.teamB().strip());
        p.setProperty("destinations", setup.destinations().strip());
        p.setProperty("returnPort", setup.returnPort().strip());
        p.setProperty("competition", setup.competition().name());
        p.setProperty("colourA", setup.fieldA().name());
        p.setProperty("goalkeeperColourA", setup.keeperA().name());
        p.setProperty("colourB", setup.fieldB().name());
        p.setProperty("goalkeeperColourB", setup.keeperB().name());
        p.setProperty("monitorPort", setup.monitorPort().strip());
        file.write(p, "Touchline GameController tab: the last game's setup");
    }
}
