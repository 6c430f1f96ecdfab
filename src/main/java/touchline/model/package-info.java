/**
 * State the views and commands read, with bounded memory and safe to read from any thread while the network
 * writes: every robot seen ({@code RobotRegistry}, {@code RobotSnapshot}, {@code RobotAuth}), the debug-option
 * protocol per robot ({@code DebugOptionSession}, {@code OptionState}; a replay's option lists, only shown:
 * {@code ShownOptions}), the team's traffic against the league's
 * limit ({@code TrafficMeter}), the league's rules as measured ({@code RuleProfile}, {@code MatchDebugRule}) and
 * the team-message budget guard ({@code TeamMessageBudget}). Each is an {@code EnvelopeSink} subscribed to the
 * stream.
 * <p>
 * May depend on: transport, security and protocol; not record (the two do not know each other).
 */
package touchline.model;
