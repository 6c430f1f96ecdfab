package touchline.protocol.gamecontroller;

/**
 * A robot's return ("RGrt") packet to the GameController, in one of its versions. Each version
 * keeps its own field order on the wire (v2: team then player; v4: player then team).
 */
public sealed interface ReturnPacket permits ReturnPacket.V1, ReturnPacket.V2, ReturnPacket.V4 {

    int MAN_PENALISE = 0;
    int MAN_UNPENALISE = 1;
    int ALIVE = 2;
    int GOALKEEPER = 3;
    int GAME_INTERRUPTION_READY = 4;

    int team();

    int player();

    /** The robot's message (v1/v2: 0 MAN_PENALISE ... ; v4: always ALIVE). */
    int message();

    /** Envelope kind, e.g. {@code gc.return.v2}. */
    String kind();

    byte[] encode();

    /** 2013 return packet, 16 bytes: u32 version 1, u16 team, u16 player, u32 message. */
    record V1(int team, int player, int message) implements ReturnPacket {
        public static final int SIZE = 16;

        @Override
        public String kind() {
            return "gc.return.v1";
        }

        @Override
        public byte[] encode() {
            var b = WireChecks.writer(SIZE);
            b.put(WireChecks.RETURN_MAGIC).putInt(1).putShort((short) team).putShort((short) player).putInt(message);
            return WireChecks.finish(b, SIZE);
        }
    }

    /** HL / SPL 2014–2017 return packet, 8 bytes: version 2, team, player (1-based), message. */
    record V2(int team, int player, int message) implements ReturnPacket {
        public static final int SIZE = 8;

        @Override
        public String kind() {
            return "gc.return.v2";
        }

        @Override
        public byte[] encode() {
            var b = WireChecks.writer(SIZE);
            b.put(WireChecks.RETURN_MAGIC).put((byte) 2).put((byte) team).put((byte) player).put((byte) message);
            return WireChecks.finish(b, SIZE);
        }
    }

    /**
     * SPL 2022– return packet, 32 bytes: version 4, playerNum, teamNum, fallen, pose (x mm, y mm,
     * theta rad), ballAge s (-1 never seen), ball (x, y mm relative to the robot).
     */
    record V4(int player, int team, int fallen, float poseX, float poseY, float poseTheta, float ballAge,
              float ballX, float ballY) implements ReturnPacket {
        public static final int SIZE = 32;

        @Override
        public int message() {
            return ALIVE;
        }

        @Override
        public String kind() {
            return "gc.return.v4";
        }

        @Override
        public byte[] encode() {
            var b = WireChecks.writer(SIZE);
            b.put(WireChecks.RETURN_MAGIC).put((byte) 4).put((byte) player).put((byte) team).put((byte) fallen);
            b.putFloat(poseX).putFloat(poseY).putFloat(poseTheta).putFloat(ballAge).putFloat(ballX).putFloat(ballY);
            return WireChecks.finish(b, SIZE);
        }
    }
}
