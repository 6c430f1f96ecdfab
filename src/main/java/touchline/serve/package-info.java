/**
 * The console as a live server in the Foxglove WebSocket protocol ({@code FoxgloveServer}, started by {@code
 * Serving} from a {@code ServeConfig}): admission and gates ({@code AccessToken}, {@code AllowedOrigins}, {@code
 * ConnectionLimits}), the channels served, raw and Foxglove-standard ({@code ChannelTable}, {@code
 * StandardChannels}), one {@code Viewer} per connection with its bounded queue ({@code PendingMessages}), the
 * console's own state as JSON channels ({@code JsonChannel}), the one command it takes, from tools on this machine
 * only ({@code OptionSwitch}: {@code touchline options --connect}), and the figures for the operator ({@code
 * ServeStats}, {@code ViewerInfo}).
 * <p>
 * May depend on: record, transport, security and protocol; not model or app. The core ({@code app.LiveServing})
 * starts it; the faces use its configuration and figures.
 */
package touchline.serve;
