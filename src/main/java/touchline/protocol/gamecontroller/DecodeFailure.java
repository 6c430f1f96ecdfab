package touchline.protocol.gamecontroller;

/** Why a GameController datagram was rejected. */
public enum DecodeFailure {
    /** The datagram is not exactly the size the format prescribes. */
    WRONG_LENGTH,
    /** The first four bytes are not the expected header ("RGme" / "RGrt"). */
    WRONG_MAGIC,
    /** The version field does not match the format. */
    WRONG_VERSION,
    /** A field holds a value the format forbids (player 0, NaN pose, ...). */
    INVALID_FIELD
}
