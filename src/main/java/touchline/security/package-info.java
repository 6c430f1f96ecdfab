/**
 * Team keys and message tags (docs/security.md): the team's secret ({@code TeamKey}), the tag ({@code MessageTag})
 * and the trailer that carries it ({@code Trailer}), the console's checks of what robots send ({@code
 * InboundVerifier}, {@code ReplayGuard}, {@code RobotBoots}) and its tagging of what it sends ({@code
 * OutboundTagger}, {@code CounterSource}); the NAO link's CURVE keys ({@code CurveKey}); key files and the key
 * directory ({@code KeyFile}, {@code KeyDir}, the only class here that touches the disk).
 * <p>
 * May depend on: protocol. Tag, trailer and replay logic are pure; nothing here reaches the transport or above.
 */
package touchline.security;
