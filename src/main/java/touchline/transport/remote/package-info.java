/**
 * Foxglove WebSocket clients. {@code Bridge}: any server (a ROS 2 robot's {@code foxglove_bridge}, the Foxglove
 * SDK's, older {@code foxglove.websocket.v1} ones) read as one robot, every channel subscribed and decoded by its
 * encoding ({@code BridgeChannels}, {@code BridgedChannel}: cdr and json through {@code protocol.ros2}, protobuf by
 * its descriptor set), its parameters, client publish and services behind the send gate ({@code BridgeStatus}; a message
 * typed as JSON goes as CDR when the server takes it, {@code ClientEncoding}; the services and their answers,
 * {@code BridgeServices}, {@code ServiceAnswer});
 * {@code ServerProbe} asks a server its name. Both ride on the core {@code FoxgloveConnection} and its
 * {@code FoxgloveSession} (subprotocols, reconnection, limits; {@code ChannelReader}, {@code StreamChannel},
 * {@code ServerReplies}), as does the remote viewer's {@code RemoteStream}.
 * <p>
 * Touchline as a viewer of another Touchline: a Foxglove WebSocket client that subscribes to
 * the robot channels a {@code touchline serve} (or a window serving to viewers) advertises and
 * rebuilds their envelopes from each channel's metadata, so the remote stream enters this
 * console's Envelope stream like live traffic, marked {@link touchline.transport.Origin#REMOTE}.
 * A transport like UDP and ZeroMQ: it turns a socket into envelopes and knows only the
 * protocol layer (codecs, kinds), so it lies in the transport layer.
 */
package touchline.transport.remote;
