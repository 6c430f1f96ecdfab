package touchline.security;

/**
 * The team key in the forms a small robot takes (docs/security.md): a C header for the firmware
 * build, or a 40-byte blob to flash ({@code "TLK1" ‖ key (32) ‖ key-id (4)}). Pure.
 */
public final class RobotKeyExport {

    public static final byte[] BLOB_MAGIC = {'T', 'L', 'K', '1'};
    public static final int BLOB_SIZE = 4 + TeamKey.SIZE + TeamKey.ID_SIZE;

    private RobotKeyExport() {
    }

    public static String cHeader(TeamKey key) {
        StringBuilder b = new StringBuilder();
        b.append("/* Touchline team key ").append(key.idHex()).append(" for the small robots' firmware, made by\n")
                .append(" * `touchline keys show --c-header`. SECRET: keep it out of version control (docs/security.md).\n")
                .append(" * Use: #include it in the board's main and set robot_config.team_key = &touchline_team_key. */\n")
                .append("#ifndef TOUCHLINE_TEAM_KEY_H\n#define TOUCHLINE_TEAM_KEY_H\n#include \"fw_auth.h\"\n\n")
                .append("static const fw_team_key touchline_team_key = {\n    {");
        bytes(b, key.secret(), "\n     ");
        b.append("},\n    {");
        bytes(b, key.id(), "");
        b.append("} /* key-id ").append(key.idHex()).append(" */\n};\n\n#endif\n");
        return b.toString();
    }

    private static void bytes(StringBuilder b, byte[] v, String wrap) {
        for (int i = 0; i < v.length; i++) {
            if (i > 0) {
                b.append(i % 8 == 0 ? "," + wrap : ", ");
            }
            b.append(String.format("0x%02x", v[i] & 0xFF));
        }
    }

    public static byte[] blob(TeamKey key) {
        byte[] out = new byte[BLOB_SIZE];
        System.arraycopy(BLOB_MAGIC, 0, out, 0, 4);
        System.arraycopy(key.secret(), 0, out, 4, TeamKey.SIZE);
        System.arraycopy(key.id(), 0, out, 4 + TeamKey.SIZE, TeamKey.ID_SIZE);
        return out;
    }
}
