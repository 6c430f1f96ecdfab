package touchline.serve;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.testing.Requirement;

import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.*;

/**
 * A second independent viewer: the Python {@code websockets} package with Google's protobuf
 * runtime connects as Foxglove would, subscribes to robot 3's status and decodes it with the
 * schema the server advertised.
 */
@Tag("interop")
class PythonFoxgloveClientTest {

    private static final String CLIENT = """
            import asyncio, base64, json, struct, sys
            import websockets
            from google.protobuf import descriptor_pb2, descriptor_pool, message_factory

            async def main(url):
                async with websockets.connect(url, subprotocols=["foxglove.websocket.v1"], open_timeout=30) as ws:
                    info = json.loads(await ws.recv())
                    assert info["op"] == "serverInfo", info
                    channel = None
                    while channel is None:
                        m = await ws.recv()
                        if isinstance(m, str):
                            op = json.loads(m)
                            if op["op"] == "advertise":
                                channel = next((c for c in op["channels"] if c["topic"] == "/robot/3/status"), None)
                    await ws.send(json.dumps({"op": "subscribe", "subscriptions": [{"id": 42, "channelId": channel["id"]}]}))
                    while True:
                        m = await ws.recv()
                        if isinstance(m, bytes) and m[0] == 1:
                            sub, stamp = struct.unpack_from("<IQ", m, 1)
                            break
                    files = descriptor_pb2.FileDescriptorSet.FromString(base64.b64decode(channel["schema"]))
                    pool = descriptor_pool.DescriptorPool()
                    for f in files.file:
                        pool.Add(f)
                    cls = message_factory.GetMessageClass(pool.FindMessageTypeByName(channel["schemaName"]))
                    status = cls.FromString(m[13:])
                    print(ws.subprotocol, sub, channel["schemaName"], status.robotName, status.batteryPercent, flush=True)

            asyncio.run(main(sys.argv[1]))
            """;

    private static boolean pythonHas(String imports) {
        try {
            Process p = new ProcessBuilder("python3", "-c", "import " + imports).redirectErrorStream(true).start();
            return p.waitFor(30, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (Exception e) {
            return false;
        }
    }

    @Test
    void thePythonWebsocketsClientDecodesARobotsStatus() throws Exception {
        Requirement.require(pythonHas("websockets, google.protobuf"),
                "python3 cannot import websockets and google.protobuf (./touchline installs them: pip install websockets)");
        try (ServedField field = new ServedField()) {
            field.publish(ServedField.status(3, "ada", 10), "status");
            Process python = new ProcessBuilder("python3", "-c", CLIENT, field.server().url("127.0.0.1"))
                    .redirectErrorStream(true).start();
            try {
                // a status is a robot's state: the one heard before subscribing comes at once
                String output = new String(python.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
                assertTrue(python.waitFor(60, TimeUnit.SECONDS));
                assertEquals(0, python.exitValue(), output);
                assertEquals("foxglove.websocket.v1 42 fumanoid.Status ada 10", output);
            } finally {
                python.destroy();
            }
        }
    }
}
