package touchline.model;

import java.util.Set;
import java.util.TreeSet;

/**
 * What a ROS 2 robot's messages told of its frames: its TF tree and its latest pose with the
 * frame it was given in. So a view can draw the robot in any frame of the tree. A pose given
 * without a frame (Pose2D, Pose, a mapped topic) is taken as it is, whatever the frame. Immutable.
 *
 * @param pose null when the robot told a tree but no pose yet
 */
public record RobotFrames(FrameTree tree, RosReadings.FramedPose pose) {

    /**
     * The frame the field is taken to be: REP 105's fixed world frame, the one a localised robot
     * places itself in. The Robots table shows a robot's pose in it when its tree leads there.
     */
    public static final String FIELD = "map";

    /** The robot's base in {@code target}: the pose there, or why there is none. */
    public FrameTree.Lookup poseIn(String target) {
        if (pose == null) {
            return new FrameTree.Lookup(null, "(no pose)");
        }
        if (pose.frame().isEmpty()) {
            return new FrameTree.Lookup(pose.pose(), "");
        }
        FrameTree.Lookup l = tree.lookup(target, pose.frame());
        return l.found() ? new FrameTree.Lookup(l.transform().then(pose.pose()), l.endedAt()) : l;
    }

    /** The pose in {@link #FIELD} when the tree leads there, else as given (null: no pose). */
    public Transform2D fieldPose() {
        FrameTree.Lookup l = poseIn(FIELD);
        return l.found() ? l.transform() : pose == null ? null : pose.pose();
    }

    /** The frames it named: its tree's and its pose's. */
    public Set<String> frames() {
        Set<String> out = new TreeSet<>(tree.frames());
        if (pose != null && !pose.frame().isEmpty()) {
            out.add(pose.frame());
        }
        return out;
    }
}
