package touchline.fuzz;

import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.ForwardedReturnPacket;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.protocol.gamecontroller.HslGameState19;
import touchline.protocol.gamecontroller.HslGameState20;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.protocol.gamecontroller.MonitorRequest;
import touchline.protocol.gamecontroller.ReturnPacket;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The GameController monitor path: every datagram is put to each decoder a monitor datagram
 * meets — the embedded GameController's monitor request ("RGTr" on 3636), the console's
 * forwarded return packet (3940) and the true data (RGTD, HSL 20 and 19). An accepted request
 * or forwarded packet encodes back to the same bytes; accepted true data to its format's size.
 */
final class GcMonitorTarget implements FuzzTarget {

    private final MonitorRequest requests = new MonitorRequest();
    private final ForwardedReturnPacket.Decoder forwarded = new ForwardedReturnPacket.Decoder();
    private final List<GameStateFormat> trueData = List.of(HslGameState20.trueData(), HslGameState19.trueData());

    @Override
    public String name() {
        return "gc-monitor";
    }

    @Override
    public void accept(byte[] input) {
        Decoded<MonitorRequest> r = requests.decode(input);
        FuzzTarget.check(r.isOk() != (r.failure() != null), "monitor request: neither value nor failure");
        if (r.isOk()) {
            FuzzTarget.check(Arrays.equals(input, requests.encode()), "an accepted request is not RGTr 0: "
                    + Arrays.toString(input));
        }
        Decoded<ForwardedReturnPacket> f = forwarded.decode(input);
        FuzzTarget.check(f.isOk() != (f.failure() != null), "forwarded packet: neither value nor failure");
        if (f.isOk()) {
            FuzzTarget.check(Arrays.equals(input, f.value().encode()), "an accepted forwarded packet does not encode"
                    + " back: " + Arrays.toString(input));
        }
        for (GameStateFormat format : trueData) {
            Decoded<GameControlData> d = format.decode(input);
            FuzzTarget.check(d.isOk() != (d.failure() != null), format.kind() + ": neither value nor failure");
            if (d.isOk()) {
                byte[] again = format.encode(d.value());
                FuzzTarget.check(again.length == format.size() && format.decode(again).isOk(),
                        format.kind() + " does not survive encode/decode");
            }
        }
    }

    /** A request, forwarded packets, and the golden HSL game states as the monitors' true data. */
    @Override
    public List<byte[]> seeds() {
        List<byte[]> seeds = new ArrayList<>();
        seeds.add(requests.encode());
        seeds.add(new ForwardedReturnPacket(new byte[]{10, 0, 5, 12},
                new ReturnPacket.V4(1, 5, 0, 1000f, -500f, 1.5f, 0.5f, 250f, 30f)).encode());
        seeds.add(new ForwardedReturnPacket(new byte[]{(byte) 192, (byte) 168, 14, 20},
                new ReturnPacket.V4(20, 14, 1, 0f, 0f, 0f, -1f, 0f, 0f)).encode());
        KnownGameStateFormats formats = new KnownGameStateFormats();
        Samples samples = new Samples();
        for (String version : List.of("hsl20", "hsl19")) {
            for (byte[] g : samples.golden("gamecontroller/" + version)) {
                KnownGameStateFormats.Match m = formats.decode(g);
                if (m != null) {
                    GameStateFormat truth = version.equals("hsl20") ? trueData.get(0) : trueData.get(1);
                    seeds.add(truth.encode(m.data()));
                }
            }
        }
        return seeds;
    }
}
