/**
 * State the views and commands read, with bounded memory and safe to read from any thread while the network
 * writes: every robot seen ({@code RobotRegistry}, {@code RobotSnapshot}, {@code RobotAuth}), the debug-option
 * protocol per robot ({@code DebugOptionSession}, {@code OptionState}; a replay's option lists, only shown:
 * {@code ShownOptions}), the team's traffic against the league's
 * limit ({@code TrafficMeter}), the league's rules as measured ({@code RuleProfile}, {@code MatchDebugRule}) and
 * the team-message budget guard ({@code TeamMessageBudget}); what a ROS 2 robot's messages say of it, by type and by
 * the user's mapping ({@code RosReadings}, {@code RosMapping}, {@code RosDiagnostics}: battery and temperature), and
 * its images, joint states, diagnostics and markers as a small robot's debug data for the views that show that
 * ({@code RosDebugData}, {@code RosTables}, {@code MarkerScene}); its frames ({@code FrameTree}, a TF tree in the
 * plane of {@code Transform2D}s, and {@code RobotFrames}, kept per robot by the registry) and the field view's model of
 * the frame chosen there ({@code FramedField}) and the relative positions view's of one robot's own frame
 * ({@code RobotCentred}; both pure, the view's thread). Each is an {@code EnvelopeSink} subscribed to the
 * stream.
 * <p>
 * May depend on: transport, security and protocol; not record (the two do not know each other).
 */
package touchline.model;
