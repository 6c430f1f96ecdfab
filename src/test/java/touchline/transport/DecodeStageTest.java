package touchline.transport;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** The UDP pipeline's second thread: order, failures, and what waits at close. */
class DecodeStageTest {

    private static Envelope numbered(int n) {
        return new Envelope(n, Direction.IN, Channel.FUMANOID, null, n % 7, "status", null, new byte[0], null);
    }

    @Test
    void publishesEveryBatchInOrderAndWhatWaitsBeforeItStops() {
        List<Long> seen = Collections.synchronizedList(new ArrayList<>());
        DecodeStage stage = new DecodeStage(e -> seen.add(e.timeMicros())).start();
        int n = 1000; // more than one full batch, and a last batch flushed by hand
        for (int i = 0; i < n; i++) {
            int k = i;
            stage.add(() -> numbered(k));
            if (i % 10 == 9) {
                stage.flush();
            }
        }
        stage.flush();
        stage.close(); // returns once the queue is empty and the thread has stopped
        assertEquals(n, seen.size());
        for (int i = 0; i < n; i++) {
            assertEquals(i, seen.get(i), "envelope " + i + " in its place");
        }
    }

    @Test
    void aDatagramWhoseDecodeFailsIsLostAndTheNextOneIsNot() {
        List<Long> seen = Collections.synchronizedList(new ArrayList<>());
        DecodeStage stage = new DecodeStage(e -> seen.add(e.timeMicros())).start();
        stage.add(() -> numbered(1));
        stage.add(() -> {
            throw new IllegalStateException("a decoder bug");
        });
        stage.add(() -> numbered(3));
        stage.flush();
        stage.close();
        assertEquals(List.of(1L, 3L), seen);
    }

    @Test
    void envelopesDecodedOnTheEventLoopAndWorkDoneHereArePublishedInOneOrder() {
        List<Long> seen = Collections.synchronizedList(new ArrayList<>());
        List<String> threads = Collections.synchronizedList(new ArrayList<>());
        DecodeStage stage = new DecodeStage(e -> {
            seen.add(e.timeMicros());
            threads.add(Thread.currentThread().getName());
        }).start();
        for (int i = 0; i < 200; i++) {
            int k = i;
            if (i % 3 == 0) {
                stage.add(() -> numbered(k)); // with a team key: decoded on the stage
            } else {
                stage.add(numbered(k)); // without: decoded on the event loop, only published here
            }
        }
        stage.flush();
        stage.close();
        assertEquals(200, seen.size());
        for (int i = 0; i < 200; i++) {
            assertEquals(i, seen.get(i), "envelope " + i + " in its place");
        }
        assertEquals(List.of("touchline-decode"), threads.stream().distinct().toList(), "published on the stage's thread");
    }

    /** The event loop takes on the HMACs while a whole batch still waits for this thread at a hand-over. */
    @Test
    void behindWhileAWholeBatchWaitsAndNotOnceEverythingIsPublished() throws Exception {
        java.util.concurrent.CountDownLatch entered = new java.util.concurrent.CountDownLatch(1);
        java.util.concurrent.CountDownLatch hold = new java.util.concurrent.CountDownLatch(1);
        DecodeStage stage = new DecodeStage(e -> {
            entered.countDown();
            try {
                hold.await(); // the model is slow: the first envelope is held until the test lets it go
            } catch (InterruptedException ex) {
                Thread.currentThread().interrupt();
            }
        }).start();
        stage.add(numbered(1));
        stage.flush();
        assertFalse(stage.behind(), "nothing waited");
        assertTrue(entered.await(30, java.util.concurrent.TimeUnit.SECONDS));
        stage.add(numbered(2));
        stage.flush();
        assertFalse(stage.behind(), "the first batch was taken: busy, but nothing waited");
        stage.add(numbered(3));
        stage.flush();
        assertTrue(stage.behind(), "the second batch still waited");
        hold.countDown();
        stage.awaitPublished();
        stage.add(numbered(4));
        stage.flush();
        assertFalse(stage.behind(), "caught up");
        stage.close();
    }

    @Test
    void awaitPublishedReturnsOnlyOnceEverythingHandedOverBeforeIsPublished() throws Exception {
        List<Long> seen = Collections.synchronizedList(new ArrayList<>());
        java.util.concurrent.CountDownLatch hold = new java.util.concurrent.CountDownLatch(1);
        DecodeStage stage = new DecodeStage(e -> {
            try {
                hold.await(); // the model is slow: the first envelope is held until the test lets it go
            } catch (InterruptedException ex) {
                Thread.currentThread().interrupt();
            }
            seen.add(e.timeMicros());
        }).start();
        for (int i = 0; i < 100; i++) {
            stage.add(numbered(i));
        }
        stage.flush();
        Thread waiter = new Thread(() -> {
            try {
                stage.awaitPublished();
            } catch (InterruptedException ex) {
                Thread.currentThread().interrupt();
            }
        });
        waiter.start();
        waiter.join(200); // bounded wait only to see that it is still blocked, not to synchronise
        assertTrue(waiter.isAlive(), "returned while envelopes were still waiting");
        hold.countDown();
        waiter.join(10_000);
        assertFalse(waiter.isAlive());
        assertEquals(100, seen.size(), "every envelope handed over before was published when it returned");
        stage.close();
    }
}
