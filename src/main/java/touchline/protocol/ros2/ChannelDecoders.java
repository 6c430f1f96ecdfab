package touchline.protocol.ros2;

/**
 * The one place that decides how a channel another tool made is decoded, for a bridge's
 * advertised channels and a bag's MCAP channels alike: {@code ros2msg}/{@code cdr},
 * {@code ros2idl}/{@code cdr}, {@code jsonschema}/{@code json} and schemaless {@code json}.
 * Protobuf is not decided here (Touchline's own descriptor handling does it).
 */
public final class ChannelDecoders {

    private final DefinitionParser parser = new DefinitionParser();

    /**
     * How the messages of a channel with this {@code messageEncoding} and schema are decoded.
     * {@code schemaName}/{@code schemaEncoding} are "" and {@code schemaData} empty when the
     * channel has no schema; {@code topic} names a schemaless JSON channel's type.
     */
    public ChannelDecoding decoding(String topic, String messageEncoding, String schemaName, String schemaEncoding,
                                    byte[] schemaData) {
        String encoding = (schemaEncoding.isEmpty() ? "no schema" : schemaEncoding) + "/" + messageEncoding;
        if (messageEncoding.equals("json")) {
            return new ChannelDecoding.Ready(new JsonDecoder(schemaName.isEmpty() ? topic : schemaName));
        }
        if (messageEncoding.equals("cdr") && (schemaEncoding.equals("ros2msg") || schemaEncoding.equals("ros2idl"))) {
            DefinitionResult r = parser.parse(schemaName, schemaEncoding,
                    new String(schemaData, java.nio.charset.StandardCharsets.UTF_8));
            if (r instanceof DefinitionResult.Parsed p) {
                return new ChannelDecoding.Ready(new CdrDecoder(p.definition()));
            }
            return new ChannelDecoding.Unsupported(encoding, "the schema " + schemaName + " does not parse: "
                    + ((DefinitionResult.Refused) r).reason());
        }
        return new ChannelDecoding.Unsupported(encoding, "encoding not supported");
    }
}
