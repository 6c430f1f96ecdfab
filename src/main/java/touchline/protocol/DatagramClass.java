package touchline.protocol;

/**
 * What a datagram on a robot port is, told apart by its first bytes (the robot port is
 * shared by FUmanoids messages, GameController packets and reliable-stream segments).
 */
public enum DatagramClass {
    FUMANOID,
    GAMECONTROLLER,
    /** Both leading bytes below 42 and not a valid FUmanoids frame: a reliable-stream segment. */
    RELIABLE_STREAM;

    /**
     * Classifies without decoding. {@code RG} is a GameController packet; {@code 00 2A} or a
     * 4-byte length that matches the datagram is a FUmanoids frame; otherwise two leading bytes
     * below 42 are a reliable-stream segment (its sequence and ack stay below 42 by design).
     * Everything else is handed to the FUmanoids decoder, which says what is wrong with it.
     */
    public static DatagramClass of(byte[] d, int length) {
        if (length >= 2 && d[0] == 'R' && d[1] == 'G') {
            return GAMECONTROLLER;
        }
        if (length >= 2 && d[0] == 0 && d[1] == Framing.MESSAGE_TYPE) {
            return FUMANOID;
        }
        if (length >= 4 && FrameCodec.lengthField(d, 0) == length - 4) {
            return FUMANOID;
        }
        if (length >= 2 && (d[0] & 0xFF) < 42 && (d[1] & 0xFF) < 42) {
            return RELIABLE_STREAM;
        }
        return FUMANOID;
    }
}
