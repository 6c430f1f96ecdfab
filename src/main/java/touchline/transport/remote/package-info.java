/**
 * Touchline as a viewer of another Touchline: a Foxglove WebSocket client that subscribes to
 * the robot channels a {@code touchline serve} (or a window serving to viewers) advertises and
 * rebuilds their envelopes from each channel's metadata, so the remote stream enters this
 * console's Envelope stream like live traffic, marked {@link touchline.transport.Origin#REMOTE}.
 * A transport like UDP and ZeroMQ: it turns a socket into envelopes and knows only the
 * protocol layer (codecs, kinds), so it lies in the transport layer.
 */
package touchline.transport.remote;
