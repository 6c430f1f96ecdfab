package touchline.model.store;

import com.google.protobuf.ByteString;
import touchline.proto.Fumanoid;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetSocketAddress;

/** Envelopes as the UDP pipeline would publish them, for store tests. */
final class StoreEnvelopes {

    private StoreEnvelopes() { }

    static Envelope in(long timeMicros, int robot, String kind, Fumanoid.Message m) {
        return new Envelope(timeMicros, Direction.IN, Channel.FUMANOID, new InetSocketAddress("127.0.0.1", 4000 + robot),
                robot, kind, m, m.toByteArray(), null);
    }

    static Envelope text(long t, int robot, String option, String text) {
        return in(t, robot, "debugText", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.debugText, Fumanoid.DebugText.newBuilder().setOption(option).setText(text).build())
                .build());
    }

    static Envelope plot(long t, int robot, String option, String series, double... values) {
        Fumanoid.DebugPlot.Builder p = Fumanoid.DebugPlot.newBuilder().setOption(option);
        for (double v : values) {
            p.addSamples(Fumanoid.PlotSample.newBuilder().setSeries(series).setValue(v));
        }
        return in(t, robot, "debugPlot", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.debugPlot, p.build()).build());
    }

    static Envelope image(long t, int robot, String option, int w, int h, int format, byte[] data) {
        return in(t, robot, "debugImage", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.debugImage, Fumanoid.DebugImage.newBuilder().setOption(option).setWidth(w)
                        .setHeight(h).setFormat(format).setData(ByteString.copyFrom(data)).build()).build());
    }
}
