package touchline.ui.frame;

/** A view on the window the frame pulse pulls: its registry ID (for the profile of refresh times) and its frame. */
public record PulledView(String id, ViewFrame frame) {
}
