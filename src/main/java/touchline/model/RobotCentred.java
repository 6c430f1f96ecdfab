package touchline.model;

import touchline.proto.Drawing;
import touchline.transport.Origin;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SortedSet;
import java.util.TreeSet;

/**
 * The relative positions view's model of a ROS 2 robot: the robot's own frame the user chose
 * ({@link #BODY} by default), and in it, through that robot's TF tree, its markers and the other
 * robots of its stream. Another robot's pose is taken in {@link RobotFrames#FIELD} ({@code map}, the
 * one frame robots share: each robot's {@code odom} is its own) by that robot's tree, or as it reports
 * it (the small robots, NAOs, a Pose2D), then moved into the chosen frame by this robot's tree. What has
 * no path is left out and counted with the reason ({@link FramedField.Picture#note}). Millimetres, x
 * forward, y left. Pure; not thread-safe: the view's thread.
 */
public final class RobotCentred {

    /** REP 105's frame of the robot's body: the frame chosen by default. */
    public static final String BODY = "base_link";

    private String chosen = FramedField.AUTO;
    private SortedSet<String> frames = new TreeSet<>();
    private FramedField.Picture picture = FramedField.Picture.EMPTY;

    /** Draws in {@code frame} from now on ({@link FramedField#AUTO} or null: {@link #BODY}). */
    public void choose(String frame) {
        chosen = frame == null ? FramedField.AUTO : frame;
    }

    /** The frame as chosen ({@link FramedField#AUTO}: {@link #BODY}). */
    public String chosen() {
        return chosen;
    }

    /** The frames the robot named at the last {@link #place}: its tree's, its pose's and its markers'. */
    public SortedSet<String> frames() {
        return frames;
    }

    /** The robot's surroundings as last placed. */
    public FramedField.Picture picture() {
        return picture;
    }

    /**
     * Places, in the chosen frame of robot {@code robotId} of stream {@code origin}, the other robots of
     * {@code robots} of that stream ({@code frames}: what that stream's robots told of their frames) and
     * the robot's {@code markers} (null: none), and keeps the picture.
     */
    public FramedField.Picture place(int robotId, Origin origin, List<RobotSnapshot> robots,
                                     Map<Integer, RobotFrames> frames, Drawing.FieldDrawing markers) {
        RobotFrames own = frames.get(robotId);
        FrameTree tree = own == null ? FrameTree.EMPTY : own.tree();
        SortedSet<String> seen = new TreeSet<>(own == null ? List.of() : own.frames());
        if (markers != null) {
            for (Drawing.FieldShape s : markers.getShapesList()) {
                if (!s.getFrame().isEmpty()) {
                    seen.add(s.getFrame());
                }
            }
        }
        this.frames = seen;
        String frame = chosen.equals(FramedField.AUTO) ? BODY : chosen;
        FrameTree.Lookup fromField = tree.lookup(frame, RobotFrames.FIELD);
        List<FramedField.Placed> placed = new ArrayList<>();
        int without = 0;
        int notIn = 0;
        String why = "";
        for (RobotSnapshot r : robots) {
            if (r.origin() != origin || r.id() == robotId) {
                continue;
            }
            FrameTree.Lookup onField = onField(r, frames.get(r.id()));
            if (onField == null) {
                without++;
                continue;
            }
            FrameTree.Lookup l = !onField.found() ? onField : fromField;
            if (!l.found()) {
                notIn++;
                why = why.isEmpty() ? l.reason() : why;
                continue;
            }
            Transform2D t = fromField.transform().then(onField.transform());
            placed.add(new FramedField.Placed(r, t.x() * 1000, t.y() * 1000, t.yaw()));
        }
        picture = markers == null ? new FramedField.Picture(frame, placed, without, notIn, why, null, 0, "")
                : FramedField.moved(frame, placed, without, notIn, why, markers, tree);
        return picture;
    }

    /** Robot {@code r}'s pose in the field (metres), why it has none there, or null when it has no position at all. */
    private static FrameTree.Lookup onField(RobotSnapshot r, RobotFrames f) {
        if (f != null && f.pose() != null) {
            return f.poseIn(RobotFrames.FIELD);
        }
        if (r.hasPosition() && Double.isFinite(r.x()) && Double.isFinite(r.y())) {
            return new FrameTree.Lookup(new Transform2D(r.x() / 1000, r.y() / 1000,
                    Double.isFinite(r.theta()) ? r.theta() : 0), RobotFrames.FIELD);
        }
        return null;
    }
}
