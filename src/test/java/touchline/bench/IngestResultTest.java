package touchline.bench;

import org.junit.jupiter.api.Test;

import java.util.Map;
import java.util.TreeMap;

import static org.junit.jupiter.api.Assertions.*;

/** The ingest benchmark's CPU figures: which thread limits the pipeline, and how a round prints them. */
class IngestResultTest {

    @Test
    void theBusiestReceivingThreadLimitsThePipelineAndTheRestIsLeftOut() {
        Map<String, Double> cpu = new TreeMap<>(Map.of(ThreadCpu.EVENT_LOOP, 2400.0, ThreadCpu.STAGE, 900.0,
                ThreadCpu.OTHER, 5000.0));
        IngestResult r = new IngestResult(10, 10, 1, cpu);
        assertEquals(2400.0, r.busiestNanosPerMessage(), "the event loop, not 'other' (GC-like helpers, timers)");
        assertEquals("event loop 2400 ns, other 5000 ns, stage (touchline-decode) 900 ns", r.cpuText());
    }

    @Test
    void withoutCpuFiguresThereIsNoBusiestThread() {
        assertTrue(Double.isNaN(new IngestResult(10, 10, 1).busiestNanosPerMessage()));
        assertEquals("", new IngestResult(10, 10, 1).cpuText());
    }

    @Test
    void threadsAreSortedIntoTheirRolesByName() {
        assertEquals(ThreadCpu.RECEIVER, ThreadCpu.role("baseline-receiver"));
        assertEquals(ThreadCpu.EVENT_LOOP, ThreadCpu.role("multiThreadIoEventLoopGroup-5-1"));
        assertEquals(ThreadCpu.STAGE, ThreadCpu.role("touchline-decode"));
        assertEquals(ThreadCpu.OTHER, ThreadCpu.role("touchline-tick"));
    }
}
