package touchline.serve;

import org.json.JSONObject;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.testing.Await;

import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.Base64;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * What a hostile or broken viewer sends: each gets that viewer an error status or a closed
 * connection, and the other viewer, subscribed all along, keeps receiving.
 */
class FoxgloveBadInputTest {

    /** A viewer subscribed to robot 3's status that must keep receiving whatever the others do. */
    private static int bystander(ServedField field, FoxgloveTestClient viewer) throws Exception {
        field.publish(ServedField.status(3, "ada", 1), "status");
        viewer.subscribe(1, viewer.awaitChannel("/robot/3/status").getInt("id"));
        Await.until("the bystander subscribed", () -> field.server().stats().subscriptions() >= 1);
        return viewer.data().size();
    }

    private static void stillReceives(ServedField field, FoxgloveTestClient viewer, int before) throws Exception {
        field.publish(ServedField.status(3, "ada", 2), "status");
        Await.until("the bystander still receives", () -> viewer.data().size() > before);
        assertFalse(viewer.closed());
        assertTrue(viewer.statuses().isEmpty(), "no status for the bystander: " + viewer.statuses());
    }

    private static String lastStatus(FoxgloveTestClient c, int count) throws InterruptedException {
        Await.until(count + " statuses", () -> c.statuses().size() >= count);
        JSONObject s = c.statuses().get(count - 1);
        assertEquals(2, s.getInt("level"), "an error status");
        return s.getString("message");
    }

    @Test
    void garbageUnknownOpsWriteOpsAndBadSubscriptionsGetAnErrorStatusAndTheConnectionGoesOn() throws Exception {
        try (ServedField field = new ServedField();
             FoxgloveTestClient bystander = new FoxgloveTestClient(field.server().port());
             FoxgloveTestClient hostile = new FoxgloveTestClient(field.server().port())) {
            int before = bystander(field, bystander);
            int status = hostile.awaitChannel("/robot/3/status").getInt("id");

            hostile.send("{this is not json");
            assertTrue(lastStatus(hostile, 1).contains("not a JSON object"));
            hostile.send("[1, 2, 3]");
            assertTrue(lastStatus(hostile, 2).contains("not a JSON object"));
            hostile.send("{\"no\":\"op\"}");
            assertTrue(lastStatus(hostile, 3).contains("without an \"op\""));
            hostile.send("{\"op\":\"fly\"}");
            assertTrue(lastStatus(hostile, 4).contains("read-only server"));
            hostile.send("{\"op\":\"advertise\",\"channels\":[{\"id\":1,\"topic\":\"/cmd\",\"encoding\":\"json\",\"schemaName\":\"x\"}]}");
            assertTrue(lastStatus(hostile, 5).contains("read-only server"));
            hostile.send("{\"op\":\"setParameters\",\"parameters\":[{\"name\":\"kick\",\"value\":1}]}");
            assertTrue(lastStatus(hostile, 6).contains("read-only server"));
            hostile.subscribe(5, 999_999);
            assertTrue(lastStatus(hostile, 7).contains("unknown channel 999999"));
            hostile.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":-1,\"channelId\":" + status + "}]}");
            assertTrue(lastStatus(hostile, 8).contains("unsigned 32-bit"));
            hostile.send("{\"op\":\"subscribe\",\"subscriptions\":\"all\"}");
            assertTrue(lastStatus(hostile, 9).contains("\"subscriptions\" array"));
            hostile.unsubscribe(42);
            assertTrue(lastStatus(hostile, 10).contains("no subscription 42"));
            hostile.send("{\"op\":\"subscribe\",\"deep\":" + "{\"a\":".repeat(5000) + "1" + "}".repeat(5001));
            assertTrue(lastStatus(hostile, 11).contains("not a JSON object"));
            // client message data (opcode 1): a viewer can never publish to robots
            hostile.sendBinary(ByteBuffer.wrap(new byte[]{1, 1, 0, 0, 0, 'k', 'i', 'c', 'k'}));
            assertTrue(lastStatus(hostile, 12).contains("read-only server"));

            hostile.subscribe(5, status);
            hostile.subscribe(5, status);
            assertTrue(lastStatus(hostile, 13).contains("subscription id 5 is in use"));
            hostile.subscribe(6, status);
            assertTrue(lastStatus(hostile, 14).contains("already subscribed to channel " + status));
            assertEquals(14, field.server().stats().badRequests());

            // after all that, the hostile viewer's good subscription works like anyone's
            Await.until("both subscribed", () -> field.server().stats().subscriptions() == 2);
            stillReceives(field, bystander, before);
            Await.until("the hostile viewer receives on its subscription", () -> !hostile.dataOf(5).isEmpty());
            assertFalse(hostile.closed());
        }
    }

    /**
     * Thousands of bad entries in one subscribe or unsubscribe (issue 37: five such frames were
     * 100 000 replies) get one status each frame, which says how many were refused and the first
     * reason; entries beyond {@link ClientOps#MAX_ENTRIES} are not looked at, and said so.
     */
    @Test
    void aFrameOfThousandsOfBadEntriesGetsOneStatus() throws Exception {
        try (ServedField field = new ServedField();
             FoxgloveTestClient bystander = new FoxgloveTestClient(field.server().port());
             FoxgloveTestClient hostile = new FoxgloveTestClient(field.server().port())) {
            int before = bystander(field, bystander);
            int status = hostile.awaitChannel("/robot/3/status").getInt("id");

            hostile.send("{\"op\":\"subscribe\",\"subscriptions\":[" + "{\"id\":1,\"channelId\":999999},".repeat(1999)
                    + "{\"id\":2,\"channelId\":" + status + "}]}");
            String first = lastStatus(hostile, 1);
            assertTrue(first.contains("1999 of 2000 entries refused, the first: subscription 0: unknown channel 999999"), first);
            hostile.send("{\"op\":\"subscribe\",\"subscriptions\":[" + "{},".repeat(9999) + "{}]}");
            String second = lastStatus(hostile, 2);
            assertTrue(second.contains(ClientOps.MAX_ENTRIES + " of " + ClientOps.MAX_ENTRIES + " entries refused"), second);
            assertTrue(second.contains("the " + (10_000 - ClientOps.MAX_ENTRIES) + " entries beyond the first "
                    + ClientOps.MAX_ENTRIES + " ignored"), second);
            hostile.send("{\"op\":\"unsubscribe\",\"subscriptionIds\":[2," + "-1,".repeat(9998) + "-1]}");
            assertTrue(lastStatus(hostile, 3).contains("entries refused, the first: subscription id 1: not an unsigned"));
            hostile.unsubscribe(77); // one more frame: its status arrives after every status of the frames before
            assertTrue(lastStatus(hostile, 4).contains("no subscription 77"));
            assertEquals(4, hostile.statuses().size(), "one status per frame: " + hostile.statuses().size());
            assertEquals(4, field.server().stats().badRequests());
            Await.until("the one good entry subscribed, then ended", () -> field.server().stats().subscriptions() == 1);
            stillReceives(field, bystander, before);
        }
    }

    @Test
    void aHugeFrameClosesThatConnectionAndAFragmentedOneIsPutTogether() throws Exception {
        try (ServedField field = new ServedField();
             FoxgloveTestClient bystander = new FoxgloveTestClient(field.server().port());
             FoxgloveTestClient fragments = new FoxgloveTestClient(field.server().port());
             FoxgloveTestClient huge = new FoxgloveTestClient(field.server().port())) {
            int before = bystander(field, bystander);
            int status = fragments.awaitChannel("/robot/3/status").getInt("id");

            String subscribe = "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":9,\"channelId\":" + status + "}]}";
            fragments.sendPart(subscribe.substring(0, 10), false);
            fragments.sendPart(subscribe.substring(10, 30), false);
            fragments.sendPart(subscribe.substring(30), true);
            Await.until("the fragmented subscribe took effect", () -> field.server().stats().subscriptions() == 2);

            huge.send("{\"op\":\"subscribe\",\"pad\":\"" + "x".repeat(ServeConfig.defaults().maxFrameBytes()) + "\"}");
            Await.until("the huge frame's connection closed", huge::closed);
            Await.until("the huge frame's viewer left the table", () -> field.server().stats().viewers() == 2);

            stillReceives(field, bystander, before);
            Await.until("the fragmented subscription receives", () -> !fragments.dataOf(9).isEmpty());
        }
    }

    @Tag("slow")
    @Test
    void aThousandConnectionsOpenedAndDroppedLeaveNoViewerBehind() throws Exception {
        try (ServedField field = new ServedField();
             FoxgloveTestClient bystander = new FoxgloveTestClient(field.server().port())) {
            int before = bystander(field, bystander);
            for (int i = 0; i < 1000; i++) {
                try (Socket s = new Socket()) {
                    s.connect(new InetSocketAddress("127.0.0.1", field.server().port()), 30_000);
                    s.setSoTimeout(30_000);
                    OutputStream out = s.getOutputStream();
                    byte[] key = new byte[16];
                    key[0] = (byte) i;
                    out.write(("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                            + "Sec-WebSocket-Key: " + Base64.getEncoder().encodeToString(key) + "\r\n"
                            + "Sec-WebSocket-Version: 13\r\nSec-WebSocket-Protocol: foxglove.websocket.v1\r\n\r\n")
                            .getBytes(StandardCharsets.US_ASCII));
                    out.flush();
                    if (i % 2 == 0) {
                        // every other one waits for the upgrade (and the welcome) and then vanishes without a close frame
                        InputStream in = s.getInputStream();
                        byte[] head = new byte[12];
                        assertEquals(12, in.readNBytes(head, 0, 12));
                        assertEquals("HTTP/1.1 101", new String(head, StandardCharsets.US_ASCII));
                    }
                }
            }
            Await.until("no viewer left but the bystander", () -> field.server().stats().viewers() == 1);
            assertEquals(1, field.server().stats().subscriptions());
            stillReceives(field, bystander, before);
        }
    }

    @Test
    void oneViewerTooManyIsToldSoAndDisconnectedWhileTheOthersWatchOn() throws Exception {
        try (ServedField field = new ServedField(ServeConfig.defaults().withPort(0).withMaxViewers(2));
             FoxgloveTestClient bystander = new FoxgloveTestClient(field.server().port());
             FoxgloveTestClient second = new FoxgloveTestClient(field.server().port())) {
            int before = bystander(field, bystander);
            second.serverInfo();
            try (FoxgloveTestClient third = new FoxgloveTestClient(field.server().port())) {
                assertTrue(lastStatus(third, 1).contains("too many viewers"));
                Await.until("the third is disconnected", third::closed);
                assertEquals(1, field.server().stats().refused());
            }
            assertEquals(2, field.server().stats().viewers());
            stillReceives(field, bystander, before);
        }
    }

    @Tag("slow")
    @Test
    void aConnectionThatNeverAsksForTheUpgradeIsClosed() throws Exception {
        try (ServedField field = new ServedField(); Socket s = new Socket()) {
            s.connect(new InetSocketAddress("127.0.0.1", field.server().port()), 30_000);
            s.setSoTimeout(60_000);
            assertEquals(-1, s.getInputStream().read(), "closed by the server after its upgrade timeout");
        }
    }

    @Tag("slow")
    @Test
    void aViewerThatSendsWithoutReadingGetsNoQueueOfStatuses() throws Exception {
        try (ServedField field = new ServedField();
             FoxgloveTestClient bystander = new FoxgloveTestClient(field.server().port());
             FoxgloveTestClient flood = new FoxgloveTestClient(field.server().port())) {
            int before = bystander(field, bystander);
            flood.serverInfo();
            flood.stopReading();
            String garbage = "{\"op\":\"" + "x".repeat(60) + "\"}";
            for (int i = 0; i < 20_000; i++) {
                flood.send(garbage);
            }
            Await.until("every flood message refused", () -> field.server().stats().badRequests() == 20_000);
            stillReceives(field, bystander, before);
            assertEquals(List.of(), bystander.statuses());
        }
    }

    /**
     * switchOption (issue 36, item 8): refused with its id while the console offers no switch,
     * and when malformed; counted; what the console's switch answers comes back with the id.
     */
    @Test
    void switchOptionIsRefusedUntilOfferedMalformedOnesAreRefusedAndTheAnswerCarriesTheId() throws Exception {
        try (ServedField field = new ServedField();
             FoxgloveTestClient tool = new FoxgloveTestClient(field.server().port())) {
            tool.send("{\"op\":\"switchOption\",\"robot\":3,\"option\":\"demo.text\",\"on\":true,\"id\":\"a\"}");
            assertTrue(lastStatus(tool, 1).contains("switches no options"));
            assertEquals("a", tool.statuses().get(0).getString("id"));
            java.util.List<String> asked = new java.util.concurrent.CopyOnWriteArrayList<>();
            field.server().offerOptionSwitches((robot, option, on) -> {
                asked.add(robot + " " + option + " " + on);
                return touchline.transport.SendResult.held("match mode, game is PLAYING");
            });
            tool.send("{\"op\":\"switchOption\",\"robot\":\"3\",\"option\":\"demo.text\",\"on\":true}");
            assertTrue(lastStatus(tool, 2).contains("numeric \"robot\""));
            tool.send("{\"op\":\"switchOption\",\"robot\":3,\"on\":true}");
            assertTrue(lastStatus(tool, 3).contains("needs an \"option\""));
            tool.send("{\"op\":\"switchOption\",\"robot\":3,\"option\":\"demo.text\",\"on\":\"yes\"}");
            assertTrue(lastStatus(tool, 4).contains("true or false"));
            assertEquals(4, field.server().stats().badRequests());
            assertEquals(List.of(), asked, "nothing malformed reached the console");
            tool.send("{\"op\":\"switchOption\",\"robot\":3,\"option\":\"demo.text\",\"on\":false,\"id\":\"b\"}");
            Await.until("the answer", () -> tool.statuses().size() >= 5);
            JSONObject answer = tool.statuses().get(4);
            assertEquals(1, answer.getInt("level"), "held back: a warning");
            assertEquals("b", answer.getString("id"));
            assertTrue(answer.getString("message").contains("PLAYING"));
            assertEquals(List.of("3 demo.text false"), asked);
        }
    }
}
