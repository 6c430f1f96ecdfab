package touchline.transport;

import org.junit.jupiter.api.Test;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.*;

/** The CPU split of the two ingest threads: the list arithmetic, and on this Linux machine the threads' real affinity. */
class CoreSplitTest {

    @Test
    void readsTheKernelsCpuLists() {
        assertEquals(List.of(0, 1), CoreSplit.parseCpuList("0-1\n"));
        assertEquals(List.of(0, 1, 2, 3, 6, 8, 9), CoreSplit.parseCpuList(" 0-3,6,8-9"));
        assertEquals(List.of(5), CoreSplit.parseCpuList("5"));
        for (String bad : new String[] {"", "a", "3-1", "1-2-3", "-1", "1,,2", "0-99999"}) {
            assertThrows(IllegalArgumentException.class, () -> CoreSplit.parseCpuList(bad), bad);
        }
    }

    @Test
    void theEventLoopTakesTheFirstHalfAndTheStageTheRest() {
        assertEquals(Optional.of(new CoreSplit("0", "1")), CoreSplit.of(List.of(0, 1)));
        assertEquals(Optional.of(new CoreSplit("0", "1-2")), CoreSplit.of(List.of(0, 1, 2)));
        assertEquals(Optional.of(new CoreSplit("0-3", "4-7")), CoreSplit.of(List.of(0, 1, 2, 3, 4, 5, 6, 7)));
        assertEquals(Optional.of(new CoreSplit("2,4", "6-7")), CoreSplit.of(List.of(2, 4, 6, 7)));
        assertEquals(Optional.empty(), CoreSplit.of(List.of(3)), "one CPU: nothing to split");
        assertEquals("ingest threads on CPUs 0 | 1", new CoreSplit("0", "1").describe());
    }

    /** Linux with at least two CPUs (this machine, CI): the started transport's two threads are on their halves. */
    @Test
    void aStartedTransportsThreadsRunOnTheirOwnHalvesAndItSaysSo() throws Exception {
        List<Integer> cpus = CoreSplit.parseCpuList(allowed(Path.of("/proc/self/status")));
        UdpTransport udp = new UdpTransport(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0),
                new touchline.protocol.MessageCodec(new touchline.protocol.MessageKinds()), e -> { }, new touchline.app.SystemClock()).start();
        try {
            Optional<CoreSplit> split = CoreSplit.of(cpus);
            if (split.isEmpty()) {
                assertTrue(udp.description().contains("one CPU: ingest threads share it"), udp.description());
                return;
            }
            assertTrue(udp.description().endsWith("; " + split.get().describe()), udp.description());
            String stage = udp.stageThreadId().orElseThrow();
            String loop = udp.eventLoopThreadId();
            assertEquals(CoreSplit.parseCpuList(split.get().stageCpus()),
                    CoreSplit.parseCpuList(allowed(Path.of("/proc/self/task", stage, "status"))));
            assertEquals(CoreSplit.parseCpuList(split.get().eventLoopCpus()),
                    CoreSplit.parseCpuList(allowed(Path.of("/proc/self/task", loop, "status"))));
        } finally {
            udp.close();
        }
    }

    @Test
    void askedToShareTheCoresItSetsNothing() throws Exception {
        System.setProperty(CoreSplit.PROPERTY, "shared");
        try {
            UdpTransport udp = new UdpTransport(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0),
                    new touchline.protocol.MessageCodec(new touchline.protocol.MessageKinds()), e -> { }, new touchline.app.SystemClock()).start();
            try {
                assertFalse(udp.description().contains("CPU"), udp.description());
                assertEquals(allowed(Path.of("/proc/self/status")),
                        allowed(Path.of("/proc/self/task", udp.stageThreadId().orElseThrow(), "status")));
            } finally {
                udp.close();
            }
        } finally {
            System.clearProperty(CoreSplit.PROPERTY);
        }
    }

    private static String allowed(Path status) throws java.io.IOException {
        return Files.readAllLines(status).stream().filter(l -> l.startsWith("Cpus_allowed_list:"))
                .map(l -> l.substring(l.indexOf(':') + 1).trim()).findFirst().orElseThrow();
    }
}
