package touchline.fuzz;

import touchline.security.Authenticity;
import touchline.security.InboundVerifier;
import touchline.security.KeyException;
import touchline.security.KeyFile;
import touchline.security.MessageTag;
import touchline.security.TeamKey;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;

/**
 * The team-key code that reads outside bytes (docs/security.md): a robot datagram's trailer
 * through the console's verifier (as it is: never verified, since nobody outside has the key;
 * tagged right: verified, with the payload exactly the input), and the same bytes as the text
 * of a key file (a {@link KeyException} or a key, nothing else).
 */
final class TrailerTarget implements FuzzTarget {

    private static final TeamKey KEY = key();

    private static TeamKey key() {
        byte[] k = new byte[TeamKey.SIZE];
        for (int i = 0; i < k.length; i++) {
            k[i] = (byte) (i * 7 + 1);
        }
        return new TeamKey(k);
    }

    private final MessageTag tag = new MessageTag(KEY);

    @Override
    public String name() {
        return "trailer";
    }

    @Override
    public void accept(byte[] input) {
        int robot = input.length > 0 ? input[0] & 0xFF : 0;
        InboundVerifier.Result r = new InboundVerifier(KEY).check(robot, input);
        FuzzTarget.check(r.authenticity() != Authenticity.VERIFIED, "made-up bytes verified: " + Arrays.toString(input));
        FuzzTarget.check(r.payloadLength() >= 0 && r.payloadLength() <= input.length, "payload outside the datagram");
        FuzzTarget.check((r.authenticity() == Authenticity.FORGED) == (r.reason() != null), "forged without a reason");

        byte[] tagged = tag.append(MessageTag.FROM_ROBOT, robot, 1L + (input.length > 1 ? input[1] & 0xFF : 0), input);
        InboundVerifier.Result ok = new InboundVerifier(KEY).check(robot, tagged);
        FuzzTarget.check(ok.authenticity() == Authenticity.VERIFIED && ok.payloadLength() == input.length,
                "a right tag was refused or the payload cut: " + ok);

        try {
            KeyFile f = KeyFile.parse("fuzz.key", new String(input, StandardCharsets.UTF_8));
            TeamKey k = f.teamKey();
            FuzzTarget.check(k.idHex().length() == 8, "key-id of a parsed key");
        } catch (KeyException expected) {
            FuzzTarget.check(expected.getMessage() != null && !expected.getMessage().isBlank(), "an error without words");
        }
    }

    @Override
    public List<byte[]> seeds() {
        byte[] payload = "status".getBytes(StandardCharsets.US_ASCII);
        String keyFile = "# team key\nteam-key = " + KEY.secretHex() + "\nkey-id = " + KEY.idHex() + "\n";
        return List.of(tag.append(MessageTag.FROM_ROBOT, 3, 5, payload), payload,
                Arrays.copyOf(tag.append(MessageTag.FROM_ROBOT, 3, 5, payload), payload.length + 20),
                keyFile.getBytes(StandardCharsets.UTF_8));
    }
}
