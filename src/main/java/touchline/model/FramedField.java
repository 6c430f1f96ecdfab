package touchline.model;

import touchline.proto.Drawing;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SortedSet;
import java.util.TreeSet;

/**
 * The field view's model of frames: the frame the user chose for the ROS 2 robots' poses and
 * markers (or {@link #AUTO}), the frames the robots told, and the robots and one robot's markers
 * placed in that frame, each by its own robot's TF tree ({@link RobotFrames}: every robot runs
 * its own ROS graph, so robot A's {@code odom} is not robot B's). What has no path to the frame is
 * left out and counted with the reason ({@link Picture#note}). Robots that told no frame (the
 * small robots, NAOs, a Pose2D) are drawn as they report. Pure; not thread-safe: the view's thread.
 */
public final class FramedField {

    /**
     * Automatic: {@link RobotFrames#FIELD} ({@code map}) when a robot's tree names it, else the one
     * frame every robot's pose is given in, else each pose as given.
     */
    public static final String AUTO = "";

    /** A robot where the field draws it: millimetres and radians in the picture's frame. */
    public record Placed(RobotSnapshot robot, double x, double y, double theta) { }

    /**
     * The field in one frame: the robots placed in it, those without a position, the poses with no
     * path to it and why (the first reason), and the markers moved into it.
     *
     * @param frame "" when each pose is drawn as given
     */
    public record Picture(String frame, List<Placed> robots, int withoutPosition, int posesNotInFrame, String posesWhy,
                          Drawing.FieldDrawing markers, int markersNotInFrame, String markersWhy) {

        static final Picture EMPTY = new Picture("", List.of(), 0, 0, "", null, 0, "");

        /** What was left out, in words: "3 poses not in map: no transform from odom"; "" for nothing. */
        public String note() {
            String poses = posesNotInFrame == 0 ? "" : " · " + posesNotInFrame + (posesNotInFrame == 1 ? " pose" : " poses")
                    + " not in " + frame + ": " + posesWhy;
            return poses + (markersNotInFrame == 0 ? "" : " · " + markersNotInFrame
                    + (markersNotInFrame == 1 ? " marker" : " markers") + " not in " + frame + ": " + markersWhy);
        }
    }

    private String chosen = AUTO;
    private Picture picture = Picture.EMPTY;
    private SortedSet<String> frames = new TreeSet<>();

    /** Draws in {@code frame} from now on ({@link #AUTO} or null: automatic). */
    public void choose(String frame) {
        chosen = frame == null ? AUTO : frame;
    }

    public String chosen() {
        return chosen;
    }

    /** The frames seen at the last {@link #place}: the robots' trees, poses and the markers'. */
    public SortedSet<String> frames() {
        return frames;
    }

    /** The field as last placed. */
    public Picture picture() {
        return picture;
    }

    /**
     * Places the robots (of both streams, with the frames each stream's robots told) and the markers
     * of robot {@code markersRobot} ({@code markers} null: none), and keeps the picture.
     */
    public Picture place(List<RobotSnapshot> robots, Map<Integer, RobotFrames> live, Map<Integer, RobotFrames> replay,
                         Drawing.FieldDrawing markers, int markersRobot, boolean markersReplayed) {
        SortedSet<String> seen = new TreeSet<>();
        Set<String> poseFrames = new TreeSet<>();
        for (Map<Integer, RobotFrames> side : List.of(live, replay)) {
            for (RobotFrames f : side.values()) {
                seen.addAll(f.frames());
                if (f.pose() != null && !f.pose().frame().isEmpty()) {
                    poseFrames.add(f.pose().frame());
                }
            }
        }
        if (markers != null) {
            for (Drawing.FieldShape s : markers.getShapesList()) {
                if (!s.getFrame().isEmpty()) {
                    seen.add(s.getFrame());
                }
            }
        }
        frames = seen;
        String frame = !chosen.equals(AUTO) ? chosen : seen.contains(RobotFrames.FIELD) ? RobotFrames.FIELD
                : poseFrames.size() == 1 ? poseFrames.iterator().next() : "";
        List<Placed> placed = new ArrayList<>(robots.size());
        int without = 0;
        int notIn = 0;
        String why = "";
        for (RobotSnapshot r : robots) {
            RobotFrames f = (r.origin() == touchline.transport.Origin.REPLAY ? replay : live).get(r.id());
            if (frame.isEmpty() || f == null || f.pose() == null) {
                if (r.hasPosition() && Double.isFinite(r.x()) && Double.isFinite(r.y())) {
                    placed.add(new Placed(r, r.x(), r.y(), r.theta()));
                } else {
                    without++;
                }
                continue;
            }
            FrameTree.Lookup l = f.poseIn(frame);
            if (l.found()) {
                placed.add(new Placed(r, l.transform().x() * 1000, l.transform().y() * 1000, l.transform().yaw()));
            } else {
                notIn++;
                why = why.isEmpty() ? l.reason() : why;
            }
        }
        RobotFrames markersFrames = markers == null ? null : (markersReplayed ? replay : live).get(markersRobot);
        picture = markers == null ? new Picture(frame, placed, without, notIn, why, null, 0, "")
                : moved(frame, placed, without, notIn, why, markers, markersFrames == null ? FrameTree.EMPTY : markersFrames.tree());
        return picture;
    }

    /** The picture with the markers moved into {@code frame} by their robot's tree. */
    static Picture moved(String frame, List<Placed> placed, int without, int notIn, String why,
                                 Drawing.FieldDrawing markers, FrameTree tree) {
        if (frame.isEmpty()) {
            return new Picture(frame, placed, without, notIn, why, markers, 0, "");
        }
        Drawing.FieldDrawing.Builder out = markers.toBuilder().clearShapes();
        int left = 0;
        String leftWhy = "";
        for (Drawing.FieldShape s : markers.getShapesList()) {
            if (s.getFrame().isEmpty() || s.getFrame().equals(frame)) {
                out.addShapes(s);
                continue;
            }
            FrameTree.Lookup l = tree.lookup(frame, s.getFrame());
            if (!l.found()) {
                left++;
                leftWhy = leftWhy.isEmpty() ? l.reason() : leftWhy;
                continue;
            }
            Drawing.FieldShape.Builder b = s.toBuilder().clearXy();
            for (int i = 0; i + 1 < s.getXyCount(); i += 2) {
                // millimetres on the field, metres in the tree
                double[] p = l.transform().apply(s.getXy(i) / 1000.0, s.getXy(i + 1) / 1000.0);
                b.addXy((float) (p[0] * 1000)).addXy((float) (p[1] * 1000));
            }
            out.addShapes(b.setFrame(frame));
        }
        return new Picture(frame, placed, without, notIn, why, out.build(), left, leftWhy);
    }
}
