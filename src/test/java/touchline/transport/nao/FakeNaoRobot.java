package touchline.transport.nao;

import com.google.protobuf.InvalidProtocolBufferException;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import touchline.proto.Nao.HAWActorRPCRequest;
import touchline.proto.Nao.HAWActorRPCResponse;
import touchline.proto.Nao.MixedValue;
import touchline.protocol.nao.MixedValueCodec;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * In-test stand-in for the robot side's RPC module: a JeroMQ ROUTER on loopback that answers
 * a few methods, replies out of order (Test.sleep), honours deadlineMillis and logs what it
 * executed. Used where the C++ binary is not built; the integration tests use the real one.
 */
public final class FakeNaoRobot implements AutoCloseable {

    private final ZContext zmq = new ZContext(1);
    private final ZMQ.Socket router;
    private final int port;
    private final Thread thread;
    private final CountDownLatch stopped = new CountDownLatch(1);
    private volatile boolean running = true;
    final List<String> executed = Collections.synchronizedList(new ArrayList<>());
    final Map<String, Object> memory = new ConcurrentHashMap<>();
    private final MixedValueCodec codec = new MixedValueCodec();

    private record Delayed(long dueNanos, byte[][] frames) {
    }

    public FakeNaoRobot(int port) {
        router = zmq.createSocket(SocketType.ROUTER);
        router.setLinger(0);
        this.port = bind(port);
        thread = new Thread(this::run, "fake-nao-" + this.port);
        thread.setDaemon(true);
        thread.start();
    }

    private int bind(int p) {
        // ":*" lets the OS choose (JeroMQ's bindToRandomPort guesses ports instead)
        router.bind("tcp://127.0.0.1:" + (p == 0 ? "*" : Integer.toString(p)));
        String endpoint = router.getLastEndpoint();
        return Integer.parseInt(endpoint.substring(endpoint.lastIndexOf(':') + 1));
    }

    public int port() {
        return port;
    }

    private void run() {
        PriorityQueue<Delayed> later = new PriorityQueue<>((a, b) -> Long.compare(a.dueNanos, b.dueNanos));
        try (ZMQ.Poller poller = zmq.createPoller(1)) {
            poller.register(router, ZMQ.Poller.POLLIN);
            while (running) {
                poller.poll(5);
                while (true) {
                    byte[] identity = router.recv(ZMQ.DONTWAIT);
                    if (identity == null) {
                        break;
                    }
                    List<byte[]> frames = new ArrayList<>();
                    while (router.hasReceiveMore()) {
                        frames.add(router.recv(0));
                    }
                    handle(identity, frames, later);
                }
                long now = System.nanoTime();
                while (!later.isEmpty() && later.peek().dueNanos <= now) {
                    sendFrames(later.poll().frames);
                }
            }
        } finally {
            zmq.close();
            stopped.countDown();
        }
    }

    private void handle(byte[] identity, List<byte[]> frames, PriorityQueue<Delayed> later) {
        if (frames.size() != 3) {
            return; // garbage: dropped, as the real broker does
        }
        HAWActorRPCRequest request;
        try {
            request = HAWActorRPCRequest.parseFrom(frames.get(2));
        } catch (InvalidProtocolBufferException e) {
            reply(identity, frames.get(0), HAWActorRPCResponse.newBuilder().setError("bad request").build().toByteArray(), 0, later);
            return;
        }
        if (request.hasDeadlineMillis() && System.currentTimeMillis() > request.getDeadlineMillis()) {
            return; // late: dropped without running
        }
        String name = request.getModule() + "." + request.getMethod();
        HAWActorRPCResponse.Builder response = HAWActorRPCResponse.newBuilder();
        long delayMs = 0;
        List<Object> params = new ArrayList<>();
        for (MixedValue p : request.getParamsList()) {
            params.add(codec.decode(p));
        }
        switch (name) {
            case "Test.echo" -> response.setReturnval(request.getParams(0));
            case "Test.void" -> { }
            case "Test.fail" -> response.setError("Test.fail: failed on purpose");
            case "Test.sleep" -> {
                delayMs = (Long) params.get(0);
                response.setReturnval(codec.encode(params.get(0)));
            }
            case "Test.garbage" -> {
                reply(identity, frames.get(0), new byte[] {(byte) 0xFF, 0x01, 0x02}, 0, later);
                executed.add(name);
                return;
            }
            case "Test.getMethodList" -> response.setReturnval(codec.encode(List.of("echo", "void", "fail", "sleep")));
            case "ALMemory.insertData" -> memory.put((String) params.get(0), params.get(1));
            case "ALMemory.getData" -> {
                Object v = memory.get((String) params.get(0));
                if (v == null) {
                    response.setError("ALMemory.getData: no key " + params.get(0));
                } else {
                    response.setReturnval(codec.encode(v));
                }
            }
            case "ALMotion.setAngles", "ALMotion.moveToward", "ALMotion.setStiffnesses", "ALMotion.moveInit",
                    "ALMotion.stopMove" -> { }
            case "ALRobotPosture.goToPosture" -> {
                if (params.get(0).equals("Stand")) {
                    response.setReturnval(codec.encode(true));
                } else {
                    response.setError("ALRobotPosture.goToPosture: unknown posture " + params.get(0));
                }
            }
            default -> response.setError("unknown method " + name);
        }
        executed.add(name + params);
        reply(identity, frames.get(0), response.build().toByteArray(), delayMs, later);
    }

    private void reply(byte[] identity, byte[] id, byte[] payload, long delayMs, PriorityQueue<Delayed> later) {
        byte[][] out = {identity, id, new byte[0], payload};
        if (delayMs == 0) {
            sendFrames(out);
        } else {
            later.add(new Delayed(System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(delayMs), out));
        }
    }

    private void sendFrames(byte[][] frames) {
        for (int i = 0; i < frames.length; i++) {
            router.send(frames[i], i < frames.length - 1 ? ZMQ.SNDMORE : 0);
        }
    }

    List<String> executedNames() {
        synchronized (executed) {
            return List.copyOf(executed);
        }
    }

    @Override
    public void close() throws InterruptedException {
        running = false;
        stopped.await(5, TimeUnit.SECONDS);
    }
}
