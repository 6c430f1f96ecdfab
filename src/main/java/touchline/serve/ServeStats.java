package touchline.serve;

/**
 * A snapshot of the live server, printed by {@code touchline serve} every few seconds.
 *
 * @param viewers        viewers connected now
 * @param subscriptions  their subscriptions, summed
 * @param channels       channels advertised
 * @param sent           messages sent to viewers since the start
 * @param dropped        messages given up for viewers that fell behind (newer ones of the same channel went out)
 * @param refused        connections refused (no or wrong token, or too many viewers)
 * @param badRequests    client messages answered with an error status (garbage, unknown or write ops)
 * @param channelsRefused new channels not served because the table was full
 * @param notConverted   envelopes not converted to the standard channels because the converter was behind
 */
public record ServeStats(int viewers, int subscriptions, int channels, long sent, long dropped, long refused,
                         long badRequests, long channelsRefused, long notConverted) {
}
