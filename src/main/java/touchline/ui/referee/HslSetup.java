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
 * goalkeeper colour (the official launcher's defaults) and the monitors' port, shown only for
 * the HSL formats. The
 * colours are checked by the official clash rule of {@link HslGame#colourConflict}.
 */
final class HslSetup {

    private final ComboBox<Competition> competition = new ComboBox<>();
    private final ComboBox<TeamColour> fieldA = colours("gc-colour-a", TeamColour.RED);
    private final ComboBox<TeamColour> keeperA = colours("gc-goalkeeper-colour-a", TeamColour.PURPLE);
    private final ComboBox<TeamColour> fieldB = colours("gc-colour-b", TeamColour.BLUE);
    private final ComboBox<TeamColour> keeperB = colours("gc-goalkeeper-colour-b", TeamColour.YELLOW);
    private final javafx.scene.control.TextField monitorPort = new javafx.scene.control.TextField(
            Integer.toString(touchline.protocol.gamecontroller.MonitorRequest.PORT));
    private final FlowPane pane;

    HslSetup() {
        competition.getItems().addAll(Competition.values());
        competition.setValue(Competition.MIDDLE_ADVANCED);
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

    private static ComboBox<TeamColour> colours(String id, TeamColour initial) {
        ComboBox<TeamColour> box = new ComboBox<>();
        box.getItems().addAll(TeamColour.values());
        box.setValue(initial);
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

    Competition competition() {
        return competition.getValue();
    }

    TeamColour[] coloursA() {
        return new TeamColour[]{fieldA.getValue(), keeperA.getValue()};
    }

    TeamColour[] coloursB() {
        return new TeamColour[]{fieldB.getValue(), keeperB.getValue()};
    }

    /**
     * The port where monitor applications (the official TeamCommunicationMonitor, a console with
     * --gc-monitor) register, as with the official GameController; null for none (left empty).
     *
     * @throws NumberFormatException when it is not a whole number
     */
    Integer monitorPort() {
        String t = monitorPort.getText().strip();
        return t.isEmpty() ? null : Integer.parseInt(t);
    }

    /** Why these colours cannot play each other, or null. */
    String conflict() {
        return HslGame.colourConflict(coloursA(), coloursB());
    }

    /** Values to remember, by key. */
    java.util.Map<String, String> values() {
        return java.util.Map.of("competition", competition().name(), "colourA", fieldA.getValue().name(),
                "goalkeeperColourA", keeperA.getValue().name(), "colourB", fieldB.getValue().name(),
                "goalkeeperColourB", keeperB.getValue().name(), "monitorPort", monitorPort.getText().strip());
    }

    /** Restores remembered values; a value that no longer names anything is left as it is. */
    void restore(java.util.function.Function<String, String> remembered) {
        set(competition, Competition.class, remembered.apply("competition"));
        set(fieldA, TeamColour.class, remembered.apply("colourA"));
        set(keeperA, TeamColour.class, remembered.apply("goalkeeperColourA"));
        set(fieldB, TeamColour.class, remembered.apply("colourB"));
        set(keeperB, TeamColour.class, remembered.apply("goalkeeperColourB"));
        String port = remembered.apply("monitorPort");
        if (port != null) {
            monitorPort.setText(port);
        }
    }

    private static <E extends Enum<E>> void set(ComboBox<E> box, Class<E> type, String name) {
        if (name == null) {
            return;
        }
        try {
            box.setValue(Enum.valueOf(type, name));
        } catch (IllegalArgumentException e) {
            // edited by hand or from another release: keep the default
        }
    }
}
