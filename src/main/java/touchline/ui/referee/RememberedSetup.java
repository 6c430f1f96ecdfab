package touchline.ui.referee;

import javafx.scene.control.ComboBox;
import javafx.scene.control.TextField;
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

    void restore(ComboBox<String> format, TextField teamA, TextField teamB, TextField destinations,
                 TextField returnPort, HslSetup hsl) {
        Properties p = file == null ? new Properties() : file.read();
        if (p.isEmpty()) {
            return;
        }
        String f = p.getProperty("format");
        if (f != null && format.getItems().contains(f)) {
            format.setValue(f);
        }
        teamA.setText(p.getProperty("teamA", teamA.getText()));
        teamB.setText(p.getProperty("teamB", teamB.getText()));
        if (System.getProperty(GameControllerTab.DESTINATIONS_PROPERTY) == null) {
            // the demo names its robots' ports: that wins over what was typed last time
            destinations.setText(p.getProperty("destinations", destinations.getText()));
        }
        returnPort.setText(p.getProperty("returnPort", returnPort.getText()));
        hsl.restore(p::getProperty);
    }

    void save(ComboBox<String> format, TextField teamA, TextField teamB, TextField destinations,
              TextField returnPort, HslSetup hsl) {
        if (file == null) {
            return;
        }
        Properties p = new Properties();
        p.setProperty("format", format.getValue());
        p.setProperty("teamA", teamA.getText().strip());
        p.setProperty("teamB", teamB.getText().strip());
        p.setProperty("destinations", destinations.getText().strip());
        p.setProperty("returnPort", returnPort.getText().strip());
        hsl.values().forEach(p::setProperty);
        file.write(p, "Touchline GameController tab: the last game's setup");
    }
}
