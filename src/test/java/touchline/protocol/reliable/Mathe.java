package touchline.protocol.reliable;

import java.nio.charset.StandardCharsets;
import java.util.Random;

/**
 * The thesis' "Mathe" acceptance test on the reliable stream. Both sides send random operands
 * 1..7 at the same time; each folds the operands it sends, and separately those it receives,
 * into a running result, alternately adding and multiplying (unsigned 32-bit, wrapping):
 * {@code r = 0; r += o1; r *= o2; r += o3; ...}. After its last operand a side sends
 * {@code END <result> <count>}; the peer compares it with what it computed from what arrived.
 * Messages are ASCII, one per segment: {@code OP <n>} and {@code END <result> <count>}
 * (the same format as the firmware's {@code fw_mathe.c}).
 */
public final class Mathe {

    private final int total;
    private final Random random;
    private int sent;
    private long sentResult;
    private int receivedCount;
    private long receivedResult;
    private boolean endQueued;
    private boolean peerEnded;
    private long peerResult = -1;
    private int peerCount = -1;
    private boolean malformed;

    public Mathe(int operands, long seed) {
        this.total = operands;
        this.random = new Random(seed);
    }

    public static long fold(long result, int index, int operand) {
        long r = index % 2 == 1 ? result + operand : result * operand;
        return r & 0xFFFF_FFFFL;
    }

    /** The next message to send, or null when everything (END included) has been handed out. */
    public byte[] next() {
        if (sent < total) {
            int op = 1 + random.nextInt(7);
            sent++;
            sentResult = fold(sentResult, sent, op);
            return ("OP " + op).getBytes(StandardCharsets.US_ASCII);
        }
        if (!endQueued) {
            endQueued = true;
            return ("END " + sentResult + " " + sent).getBytes(StandardCharsets.US_ASCII);
        }
        return null;
    }

    public void receive(byte[] message) {
        String m = new String(message, StandardCharsets.US_ASCII);
        String[] parts = m.split(" ");
        try {
            if (parts.length == 2 && parts[0].equals("OP")) {
                int op = Integer.parseInt(parts[1]);
                if (op < 1 || op > 7) {
                    malformed = true;
                    return;
                }
                receivedCount++;
                receivedResult = fold(receivedResult, receivedCount, op);
                return;
            }
            if (parts.length == 3 && parts[0].equals("END")) {
                peerResult = Long.parseLong(parts[1]);
                peerCount = Integer.parseInt(parts[2]);
                peerEnded = true;
                return;
            }
        } catch (NumberFormatException e) {
            // falls through to malformed
        }
        malformed = true;
    }

    public boolean peerEnded() {
        return peerEnded;
    }

    /** What arrived matches what the peer says it sent, and nothing malformed came. */
    public boolean agrees() {
        return peerEnded && !malformed && peerCount == receivedCount && peerResult == receivedResult;
    }

    public String summary() {
        return "sent " + sent + " operands (result " + sentResult + "), received " + receivedCount
                + " (result " + receivedResult + "), peer says " + peerCount + " (result " + peerResult + ")"
                + (malformed ? ", malformed messages seen" : "");
    }
}
