/**
 * The ROS 2 robots' commands in the window: the bridges' parameters ({@code ParametersView}) and
 * publishing on a topic or calling a service ({@code RosCommandsView}), each through the core's
 * {@code app.bridges.RosBridges} and held during play like a debug option.
 */
package touchline.ui.ros2;
