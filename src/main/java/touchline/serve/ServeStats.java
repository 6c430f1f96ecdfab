package touchline.serve;

/**
 * A snapshot of the live server, printed by {@code touchline serve} every few seconds.
 *
 * @param viewers        viewers connected now
 * @param subscriptions  their subscriptions, summed
 * @param channels       channels advertised
 * @param sent           messages sent to viewers since the start
 * @param dropped        messages given up for viewers that fell behind (newer ones of the same channel went out)
 * @param refused        connections refused or cut, all reasons together
 * @param refusedBy      the same by reason, in words (only those that happened), e.g. "upgrade deadline" → 7
 * @param upgrading      connections open now that have not finished their WebSocket upgrade
 * @param badRequests    client messages answered with an error status (garbage, unknown or write ops)
 * @param channelsRefused new channels not served because the table was full
 * @param notConverted   envelopes not converted to the standard channels because the converter was behind
 */
public record ServeStats(int viewers, int subscriptions, int channels, long sent, long dropped, long refused,
                         java.util.Map<String, Long> refusedBy, int upgrading, long badRequests, long channelsRefused, long notConverted) {

    /** "refused 40 (upgrade slots full 33, upgrade deadline 7)", "refused 0": the status line's words. */
    public String refusedInWords() {
        StringBuilder b = new StringBuilder("refused ").append(refused);
        refusedBy.forEach((why, n) -> b.append(b.indexOf("(") < 0 ? " (" : ", ").append(why).append(' ').append(n));
        return refusedBy.isEmpty() ? b.toString() : b.append(')').toString();
    }
}
