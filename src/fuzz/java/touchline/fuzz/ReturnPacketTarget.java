package touchline.fuzz;

import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.ReturnPacket;
import touchline.protocol.gamecontroller.ReturnPacketDecoder;

import java.util.Arrays;
import java.util.List;

/** A GameController return packet, every version; an accepted one encodes back to the same bytes. */
final class ReturnPacketTarget implements FuzzTarget {

    private final ReturnPacketDecoder decoder = new ReturnPacketDecoder();

    @Override
    public String name() {
        return "return-packet";
    }

    @Override
    public void accept(byte[] input) {
        Decoded<ReturnPacket> d = decoder.decode(input);
        FuzzTarget.check(d.isOk() != (d.failure() != null), "neither value nor failure");
        if (d.isOk()) {
            byte[] again = d.value().encode();
            FuzzTarget.check(decoder.decode(again).isOk() && decoder.decode(again).value().equals(d.value()),
                    "an accepted packet does not survive encode/decode: " + Arrays.toString(input));
        }
    }

    @Override
    public List<byte[]> seeds() {
        return List.of(new ReturnPacket.V1(13, 2, 1).encode(), new ReturnPacket.V2(13, 2, 2).encode(),
                new ReturnPacket.V4(2, 13, 0, 100f, -200f, 0.5f, 1.5f, 300f, 20f).encode());
    }
}
