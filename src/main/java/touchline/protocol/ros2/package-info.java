/**
 * ROS 2 and JSON messages of channels other tools make (a Foxglove bridge's, a ROS 2 bag's),
 * decoded by their definitions at run time, with no ROS installation. Pure: no I/O, no threads.
 * <p>
 * <b>The API</b> (stable; what the bridges and the replay use):
 * <ul>
 * <li>{@link touchline.protocol.ros2.ChannelDecoders}{@code .decoding(topic, messageEncoding,
 *     schemaName, schemaEncoding, schemaData)} → {@link touchline.protocol.ros2.ChannelDecoding}:
 *     {@code Ready(MessageDecoder)} for {@code ros2msg/cdr}, {@code ros2idl/cdr},
 *     {@code jsonschema/json} and schemaless {@code json}; {@code Unsupported(encoding, reason)}
 *     otherwise (also when the definition does not parse; the reason names the line). Decide once
 *     per channel, keep the decoder.</li>
 * <li>{@link touchline.protocol.ros2.MessageDecoder}{@code .decode(bytes[, offset, length])} →
 *     {@link touchline.protocol.ros2.DecodeResult}: {@code Decoded(RosMessage)} or
 *     {@code Undecodable(reason)}. Never throws, memory bounded by the input; thread-safe.
 *     {@code typeName()} is the channel's type ({@code sensor_msgs/msg/Image}).</li>
 * <li>{@link touchline.protocol.ros2.RosMessage}: the decoded tree. {@code typeName()},
 *     {@code get(field)}, {@code at("pose.position.x")}, {@code number("position[3]")} (NaN when
 *     not a number), {@code forEachNumber((path, value) -> ...)} and {@code numericPaths()} for
 *     Plot fields and CSV, {@code line(max)} for the network console, {@code text(max)} indented.
 *     Value types are listed in its Javadoc (arrays stay Java arrays: an image's data is one
 *     {@code byte[]}).</li>
 * <li>{@link touchline.protocol.ros2.RosImage}{@code .frame(RosMessage)}: a {@code sensor_msgs/msg/Image}
 *     (rgb8, bgr8, rgba8, bgra8, mono8, yuv422, yuyv) as RGB or grey pixels, a {@code CompressedImage}
 *     (jpeg, png) as its file bytes, or {@code Refused(reason)}.</li>
 * <li>Below these: {@link touchline.protocol.ros2.DefinitionParser} →
 *     {@link touchline.protocol.ros2.DefinitionResult} ({@code Parsed(MessageDefinition)} or
 *     {@code Refused(reason, line)}); {@link touchline.protocol.ros2.MessageDefinition},
 *     {@link touchline.protocol.ros2.MessageType}, {@link touchline.protocol.ros2.Field},
 *     {@link touchline.protocol.ros2.Primitive}; {@link touchline.protocol.ros2.CdrDecoder} and
 *     {@link touchline.protocol.ros2.JsonDecoder}, the two decoders.</li>
 * <li>The other way, for a client publish: {@link touchline.protocol.ros2.CdrEncoder}{@code .encode(json)} →
 *     {@link touchline.protocol.ros2.EncodeResult}: {@code Encoded(bytes)} (little-endian CDR, what
 *     {@code mcap_ros2} writes) or {@code Refused(reason)} naming the field.</li>
 * </ul>
 * <b>The envelope shape</b> for such a message (replay of a bag today, a bridge's live data the
 * same way): {@code Envelope.ros()} holds the {@code RosMessage} (its component after
 * {@code authenticity}; {@code message} stays null, it is for protobuf), {@code kind} is the topic,
 * {@code raw} the message bytes exactly as received (CDR with its 4-byte header, or the JSON text),
 * and an {@code Undecodable} message is an envelope with {@code error} = its reason and
 * {@code ros} null (counted as malformed like any other). A bag's channels play as
 * {@code Channel.FOREIGN} with robot {@code NO_ROBOT}.
 * <p>
 * May depend on: nothing of Touchline's; org.json for JSON (ArchitectureTest).
 */
package touchline.protocol.ros2;
