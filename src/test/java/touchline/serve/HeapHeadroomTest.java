package touchline.serve;

import com.sun.management.HotSpotDiagnosticMXBean;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import java.lang.management.ManagementFactory;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The soft heap limit while serving: raised, put back, never lowered (this JVM's own flag). */
class HeapHeadroomTest {

    private final HotSpotDiagnosticMXBean vm = ManagementFactory.getPlatformMXBean(HotSpotDiagnosticMXBean.class);
    private String original;

    @BeforeEach
    void remember() {
        original = vm.getVMOption("SoftMaxHeapSize").getValue();
        vm.setVMOption("SoftMaxHeapSize", Long.toString(64L << 20));
    }

    @AfterEach
    void putBack() {
        vm.setVMOption("SoftMaxHeapSize", original);
    }

    private long softMax() {
        return Long.parseLong(vm.getVMOption("SoftMaxHeapSize").getValue());
    }

    @Test
    void aLowerLimitIsRaisedWhileItIsHeldAndPutBackAfter() {
        try (HeapHeadroom h = new HeapHeadroom(96L << 20)) {
            assertTrue(h.raised());
            assertEquals(96L << 20, softMax());
        }
        assertEquals(64L << 20, softMax());
    }

    @Test
    void aHigherLimitIsLeftAsItIs() {
        try (HeapHeadroom h = new HeapHeadroom(32L << 20)) {
            assertFalse(h.raised());
            assertEquals(64L << 20, softMax());
        }
        assertEquals(64L << 20, softMax());
    }

    @Test
    void neverBeyondTheMaximumHeap() {
        long max = Long.parseLong(vm.getVMOption("MaxHeapSize").getValue());
        try (HeapHeadroom h = new HeapHeadroom(max * 4)) {
            assertEquals(max, softMax());
        }
        assertEquals(64L << 20, softMax());
    }
}
