package touchline.transport.nao;

import com.google.protobuf.ByteString;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import touchline.proto.Nao.CamRequest;
import touchline.proto.Nao.CamResponse;
import touchline.protocol.nao.CameraFormat;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.concurrent.atomic.AtomicInteger;

/** In-test stand-in for the camera server: a REP socket with the configure / fetch contract. */
public final class FakeNaoCamera implements AutoCloseable {

    private final ZContext zmq = new ZContext(1);
    private final ZMQ.Socket rep;
    private final int port;
    private final Thread thread;
    private volatile boolean running = true;
    final AtomicInteger fetches = new AtomicInteger();
    final AtomicInteger configures = new AtomicInteger();

    public FakeNaoCamera() {
        rep = zmq.createSocket(SocketType.REP);
        rep.setLinger(0);
        rep.setReceiveTimeOut(50);
        rep.bind("tcp://127.0.0.1:*");
        String endpoint = rep.getLastEndpoint();
        port = Integer.parseInt(endpoint.substring(endpoint.lastIndexOf(':') + 1));
        thread = new Thread(this::run, "fake-camera-" + port);
        thread.setDaemon(true);
        thread.start();
    }

    public int port() {
        return port;
    }

    private void run() {
        int resolution = -1;
        try {
            while (running) {
                byte[] request = rep.recv(0);
                if (request == null) {
                    continue;
                }
                CamResponse.Builder reply = CamResponse.newBuilder();
                if (request.length > 0) {
                    CamRequest r = CamRequest.parseFrom(request);
                    if (r.hasResolution() && !CameraFormat.isKnownResolution(r.getResolution())) {
                        reply.setError("unknown resolution " + r.getResolution());
                    } else {
                        resolution = r.hasResolution() ? r.getResolution() : resolution;
                        configures.incrementAndGet();
                    }
                } else if (resolution < 0) {
                    reply.setError("camera not configured");
                } else {
                    fetches.incrementAndGet();
                    reply.setImageData(ByteString.copyFrom(jpeg(CameraFormat.width(resolution), CameraFormat.height(resolution))));
                }
                rep.send(reply.build().toByteArray(), 0);
            }
        } catch (IOException e) {
            throw new IllegalStateException(e);
        } finally {
            zmq.close();
        }
    }

    private static byte[] jpeg(int w, int h) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB), "jpg", out);
        return out.toByteArray();
    }

    @Override
    public void close() throws InterruptedException {
        running = false;
        thread.join(2000);
    }
}
