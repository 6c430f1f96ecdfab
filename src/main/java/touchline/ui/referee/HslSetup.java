package touchline.ui.referee;

import javafx.scene.Node;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.layout.FlowPane;
import javafx.scene.layout.HBox;
import javafx.util.StringConverter;
import touchline.game.hsl.Competition;
import touchline.game.hsl.HslGame;
import touchline.protocol.gamecontroller.TeamColour;
import touchline.transport.gamecontroller.GcProfile;

/**
 * The setup of an HSL game in the tab: the competition, each team's field player and
 * goalkeeper colour and the monitors' port, shown only for the HSL formats. What they hold is a
 * {@link GameSetup}'s; the colours are checked when the game starts ({@link HslGame#colourConflict}).
 */
final class HslSetup {

    private final ComboBox<Competition> competition = new ComboBox<>();
    private final ComboBox<TeamColour> fieldA = colours("gc-colour-a");
    private final ComboBox<TeamColour> keeperA = colours("gc-goalkeeper-colour-a");
    private final ComboBox<TeamColour> fieldB = colours("gc-colour-b");
    private final ComboBox<TeamColour> keeperB = colours("gc-goalkeeper-colour-b");
    private final javafx.scene.control.TextField monitorPort = new javafx.scene.control.TextField();
    private final FlowPane pane;

    HslSetup() {
        competition.getItems().addAll(Competition.values());
        competition.setId("gc-competition");
        competition.setConverter(lowerCase(Competition.class));
        pane = new FlowPane(16, 8, new HBox(8, new Label("Competition"), competition),
                new HBox(8, new Label("Team A wears"), fieldA, new Label("goalkeeper"), keeperA),
                new HBox(8, new Label("Team B wears"), fieldB, new Label("goalkeeper"), keeperB),
                new HBox(8, new Label("Monitors register on UDP"), monitorPort));
        monitorPort.setId("gc-monitor-port");
        monitorPort.setPrefColumnCount(5);
        monitorPort.setPromptText("none");
        for (Node row : pane.getChildren()) {
            ((HBox) row).setAlignment(javafx.geometry.Pos.CENTER_LEFT);
        }
    }

    /** Names as the CLI and the official launcher write them: {@code middle_advanced}, {@code red}. */
    private static <E extends Enum<E>> StringConverter<E> lowerCase(Class<E> type) {
        return new StringConverter<>() {
            @Override
            public String toString(E value) {
                return value == null ? "" : value.name().toLowerCase(java.util.Locale.ROOT);
            }

            @Override
            public E fromString(String text) {
                return Enum.valueOf(type, text.toUpperCase(java.util.Locale.ROOT));
            }
        };
    }

    private static ComboBox<TeamColour> colours(String id) {
        ComboBox<TeamColour> box = new ComboBox<>();
        box.getItems().addAll(TeamColour.values());
        box.setId(id);
        box.setConverter(lowerCase(TeamColour.class));
        return box;
    }

    Node node() {
        return pane;
    }

    /** Shown for the HSL formats only (the older ones have no competition and one colour). */
    void showFor(GcProfile profile) {
        boolean on = profile != null && profile.hsl();
        pane.setVisible(on);
        pane.setManaged(on);
    }

    /** Shows {@code setup}'s HSL values. */
    void fill(GameSetup setup) {
        competition.setValue(setup.competition());
        fieldA.setValue(setup.fieldA());
        keeperA.setValue(setup.keeperA());
        fieldB.setValue(setup.fieldB());
        keeperB.setValue(setup.keeperB());
        monitorPort.setText(setup.monitorPort());
    }

    Competition competition() {
        return competition.getValue();
    }

    TeamColour fieldA() {
        return fieldA.getValue();
    }

    TeamColour keeperA() {
        return keeperA.getValue();
    }

    TeamColour fieldB() {
        return fieldB.getValue();
    }

    TeamColour keeperB() {
        return keeperB.getValue();
    }

    /** The monitors' port as typed. */
    String monitorPort() {
        return monitorPort.getText();
    }
}
