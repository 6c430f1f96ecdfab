package touchline.transport;

import touchline.protocol.gamecontroller.KnownGameStateFormats;

/**
 * The game state an envelope carries, recognised the one way the console recognises game-state
 * datagrams ({@link KnownGameStateFormats}: magic, version and exact length), for every reader
 * of the envelope stream: the timeline's events, the live server's state channel, a remote
 * console's match mode, a session's clock alignment. Only a well-formed GameController envelope
 * carries one: what the live path flagged (a rejected packet, an intruder, true data this
 * console did not register for) carries none.
 */
public final class GameStateReader {

    private final KnownGameStateFormats formats = new KnownGameStateFormats();

    /** A GameController envelope without an error whose bytes start with a game-state magic. */
    public static boolean isGameState(Envelope e) {
        return e.channel() == Channel.GAMECONTROLLER && !e.isMalformed() && KnownGameStateFormats.isGameState(e.raw());
    }

    /** The format and content, or null when the envelope carries no game state a known format accepts. */
    public KnownGameStateFormats.Match read(Envelope e) {
        return isGameState(e) ? formats.decode(e.raw()) : null;
    }
}
