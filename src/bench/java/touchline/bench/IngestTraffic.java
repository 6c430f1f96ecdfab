package touchline.bench;

import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;

import java.util.ArrayList;
import java.util.List;

/** The datagrams the ingest benchmark sends: what a team's robots send during a match. */
final class IngestTraffic {

    /** Six robots' realistic mix (IDs from {@code firstRobot}): keep-alives, plots, text, region growing. */
    List<byte[]> sixRobots(int firstRobot) {
        FrameCodec frames = new FrameCodec();
        List<byte[]> out = new ArrayList<>();
        for (int robot = firstRobot; robot < firstRobot + 6; robot++) {
            out.add(frames.encode(Framing.LEGACY, Fumanoid.Message.newBuilder().setRobotID(robot)
                    .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTimestamp(123456789L).setTeamID(13)
                            .setTimeOnline(42).setActiveRole("striker").setCurrentState("walking").setRobotName("fu" + robot)
                            .setBatteryPercent(80).setRobotPosition(Fumanoid.Position.newBuilder().setX(1200).setY(-300).setTheta(0.5f))
                            .build()).build().toByteArray()));
            Fumanoid.DebugPlot.Builder plot = Fumanoid.DebugPlot.newBuilder().setOption("demo.plotter").setTimestamp(1);
            for (int s = 0; s < 4; s++) {
                plot.addSamples(Fumanoid.PlotSample.newBuilder().setSeries("series" + s).setValue(s * 0.5));
            }
            out.add(frames.encode(Framing.LENGTH_PREFIX, Fumanoid.Message.newBuilder().setRobotID(robot)
                    .setExtension(Fumanoid.debugPlot, plot.build()).build().toByteArray()));
            out.add(frames.encode(Framing.LEGACY, Fumanoid.Message.newBuilder().setRobotID(robot)
                    .setExtension(Fumanoid.debugText, Fumanoid.DebugText.newBuilder().setOption("demo.text")
                            .setText("ball seen at 1.2 m, bearing 12 deg").build()).build().toByteArray()));
            Fumanoid.RegionGrowing.Builder regions = Fumanoid.RegionGrowing.newBuilder().setOption("havimo.region")
                    .setFrameWidth(160).setFrameHeight(120);
            for (int r = 0; r < 5; r++) {
                regions.addRegions(Fumanoid.Region.newBuilder().setColorClass(r).setX1(r * 10).setY1(r * 5).setX2(r * 10 + 20).setY2(r * 5 + 12));
            }
            out.add(frames.encode(Framing.LEGACY, Fumanoid.Message.newBuilder().setRobotID(robot)
                    .setExtension(Fumanoid.regionGrowing, regions.build()).build().toByteArray()));
        }
        return out;
    }
}
