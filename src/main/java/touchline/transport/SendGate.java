package touchline.transport;

import java.util.Optional;

/**
 * Decides whether the console may send to robots right now (match mode: nothing but
 * GameController packets while a game is on). Returns the {@link Hold} when sending is held back.
 */
@FunctionalInterface
public interface SendGate {

    Optional<Hold> hold();

    static SendGate open() {
        return Optional::empty;
    }
}
