package touchline.model.store;

import com.google.protobuf.ByteString;
import touchline.proto.Fumanoid;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetSocketAddress;

/** Envelopes as the UDP pipeline would publish them, for store and view tests. */
public final class StoreEnvelopes {

    private StoreEnvelopes() { }

    public static Envelope in(long timeMicros, int robot, String kind, Fumanoid.Message m) {
        return new Envelope(timeMicros, Direction.IN, Channel.FUMANOID, new InetSocketAddress("127.0.0.1", 4000 + robot),
                robot, kind, m, m.toByteArray(), null);
    }

    /** A ROS 2 robot's message {@code m} on {@code topic}, as a bridge hands it on. */
    public static Envelope ros(long timeMicros, int robot, String topic, touchline.protocol.ros2.RosMessage m) {
        return new Envelope(timeMicros, Direction.IN, Channel.BRIDGE, new InetSocketAddress("127.0.0.1", 8765), robot, topic,
                null, new byte[0], null, touchline.transport.Origin.LIVE, touchline.security.Authenticity.NOT_CHECKED, m);
    }

    public static Envelope text(long t, int robot, String option, String text) {
        return in(t, robot, "debugText", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.debugText, Fumanoid.DebugText.newBuilder().setOption(option).setText(text).build())
                .build());
    }

    public static Envelope plot(long t, int robot, String option, String series, double... values) {
        Fumanoid.DebugPlot.Builder p = Fumanoid.DebugPlot.newBuilder().setOption(option);
        for (double v : values) {
            p.addSamples(Fumanoid.PlotSample.newBuilder().setSeries(series).setValue(v));
        }
        return in(t, robot, "debugPlot", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.debugPlot, p.build()).build());
    }

    public static Envelope image(long t, int robot, String option, int w, int h, int format, byte[] data) {
        return in(t, robot, "debugImage", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.debugImage, Fumanoid.DebugImage.newBuilder().setOption(option).setWidth(w)
                        .setHeight(h).setFormat(format).setData(ByteString.copyFrom(data)).build()).build());
    }

    public static Envelope status(long t, int robot) {
        return in(t, robot, "status", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).setRobotName("bad-" + robot)
                        .build()).build());
    }

    public static Envelope optionList(long t, int robot, String option, int kind) {
        return in(t, robot, "debugOptionList", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.debugOptionList, Fumanoid.DebugOptionList.newBuilder().addOptions(
                        Fumanoid.DebugOption.newBuilder().setName(option).setKind(kind)).build()).build());
    }

    public static Envelope regions(long t, int robot, String option, int[]... boxes) {
        Fumanoid.RegionGrowing.Builder r = Fumanoid.RegionGrowing.newBuilder().setOption(option).setFrameWidth(160)
                .setFrameHeight(120);
        for (int[] b : boxes) {
            r.addRegions(Fumanoid.Region.newBuilder().setColorClass(1).setX1(b[0]).setY1(b[1]).setX2(b[2]).setY2(b[3]));
        }
        return in(t, robot, "regionGrowing", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.regionGrowing, r.build()).build());
    }
}
