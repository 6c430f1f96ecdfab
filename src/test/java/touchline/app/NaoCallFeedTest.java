package touchline.app;

import org.junit.jupiter.api.Test;
import touchline.proto.Nao.HAWActorRPCRequest;
import touchline.proto.Nao.HAWActorRPCResponse;
import touchline.protocol.nao.MixedValueCodec;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import java.net.InetSocketAddress;
import java.util.concurrent.atomic.AtomicBoolean;

import static org.junit.jupiter.api.Assertions.*;

/** The NAO calls' newest outcome read from the Envelope stream, as a viewer or a replay sees them. */
class NaoCallFeedTest {

    private static final InetSocketAddress NAO = InetSocketAddress.createUnresolved("10.0.0.7", 5555);

    private final AtomicBoolean replaying = new AtomicBoolean();
    private final NaoCallFeed feed = new NaoCallFeed(replaying::get);

    /** As the console's two streams hand it on: a replayed envelope to the replay's slot, any other to the live one. */
    private void publish(Envelope e) {
        (e.replayed() ? feed.replay() : feed.live()).accept(e);
    }

    private static Envelope call(String module, String method, Origin origin) {
        HAWActorRPCRequest r = HAWActorRPCRequest.newBuilder().setModule(module).setMethod(method).build();
        return new Envelope(1, Direction.OUT, Channel.NAO_RPC, NAO, Envelope.NO_ROBOT, module + "." + method, r,
                r.toByteArray(), null, origin);
    }

    private static Envelope reply(String kind, HAWActorRPCResponse r, Origin origin) {
        return new Envelope(2, Direction.IN, Channel.NAO_RPC, NAO, Envelope.NO_ROBOT, kind, r, r.toByteArray(), null,
                origin);
    }

    @Test
    void saysTheNewestCallAndThenItsValueErrorOrDone() {
        assertEquals("", feed.line());
        assertEquals(0, feed.version());
        publish(call("ALTextToSpeech", "getVolume", Origin.REMOTE));
        assertEquals("ALTextToSpeech.getVolume: " + NaoCallFeed.NO_REPLY_YET, feed.line());
        long sent = feed.version();
        publish(reply("ALTextToSpeech.getVolume", HAWActorRPCResponse.newBuilder()
                .setReturnval(new MixedValueCodec().encode(80L)).build(), Origin.REMOTE));
        assertEquals("ALTextToSpeech.getVolume: 80", feed.line());
        assertTrue(feed.version() > sent);

        publish(reply("ALMotion.fly", HAWActorRPCResponse.newBuilder().setError("no method fly").build(),
                Origin.REMOTE));
        assertEquals("ALMotion.fly: error: no method fly", feed.line());
        publish(reply("ALMotion.wakeUp", HAWActorRPCResponse.getDefaultInstance(), Origin.LIVE));
        assertEquals("ALMotion.wakeUp: done", feed.line());
    }

    @Test
    void anUnreadableOrStrayReplyIsSaidAsSuch() {
        publish(new Envelope(1, Direction.IN, Channel.NAO_RPC, NAO, Envelope.NO_ROBOT, "malformed", null,
                new byte[]{1, 2}, "expected [8-byte id][empty][reply], got 1 frames", Origin.REMOTE));
        assertEquals("unreadable NAO reply: expected [8-byte id][empty][reply], got 1 frames", feed.line());
        publish(new Envelope(2, Direction.IN, Channel.NAO_RPC, NAO, Envelope.NO_ROBOT, "ALMotion.rest", null,
                new byte[]{(byte) 0xff}, null, Origin.REMOTE));
        assertTrue(feed.line().startsWith("ALMotion.rest: unreadable reply"), feed.line());
        publish(reply("stray", HAWActorRPCResponse.getDefaultInstance(), Origin.REMOTE));
        assertEquals("a reply to no waiting call: done", feed.line());
    }

    @Test
    void ignoresWhatIsNoNaoCall() {
        HAWActorRPCResponse r = HAWActorRPCResponse.getDefaultInstance();
        publish(new Envelope(1, Direction.IN, Channel.NAO_CAMERA, NAO, Envelope.NO_ROBOT, "frame", r,
                r.toByteArray(), null, Origin.REMOTE));
        assertEquals("", feed.line());
        assertEquals(0, feed.version());
    }

    @Test
    void replayedCallsAreShownWhileAReplayIsOpenAndGoWithIt() {
        publish(reply("ALMotion.wakeUp", HAWActorRPCResponse.getDefaultInstance(), Origin.LIVE));
        publish(call("ALRobotPosture", "goToPosture", Origin.REPLAY));
        assertEquals("ALMotion.wakeUp: done", feed.line(), "no replay open: the live calls");
        replaying.set(true);
        assertTrue(feed.showsReplay());
        assertEquals("ALRobotPosture.goToPosture: " + NaoCallFeed.NO_REPLY_YET, feed.line());
        long replayed = feed.version();
        feed.restartReplay();
        assertEquals("", feed.line(), "the replay jumped: its calls start afresh");
        assertTrue(feed.version() > replayed);
        replaying.set(false);
        assertEquals("ALMotion.wakeUp: done", feed.line());
    }
}
