package touchline.ui.viewers;

import touchline.app.LiveServing;
import touchline.serve.AccessToken;
import touchline.serve.FoxgloveServer;
import touchline.serve.ServeConfig;

import java.security.SecureRandom;
import java.util.Optional;

/**
 * The window's "Serve to viewers": starts and stops serving the console's stream through the
 * same {@link LiveServing} as {@code touchline serve}, on this machine only or (with a generated token)
 * to other machines. One per window; the menu, its shortcut and the Viewers view share it.
 * Errors (a port in use) are sentences, never exceptions.
 */
public final class ServeToggle implements AutoCloseable {

    private final LiveServing live;
    private boolean serving;
    private int port = ServeConfig.DEFAULT_PORT;
    private boolean beyondThisMachine;
    private String said = "Not serving.";

    public ServeToggle(LiveServing live) {
        this.live = live;
    }

    public synchronized void setPort(int port) {
        this.port = port;
    }

    public synchronized int port() {
        return port;
    }

    /** Other machines may watch (all addresses, with a generated token) or only this one (loopback, no token). */
    public synchronized void setBeyondThisMachine(boolean beyond) {
        this.beyondThisMachine = beyond;
    }

    public synchronized boolean beyondThisMachine() {
        return beyondThisMachine;
    }

    public synchronized boolean serving() {
        return serving;
    }

    /** Starts when stopped, stops when serving; returns the sentence to show. */
    public synchronized String toggle() {
        return serving ? stop() : start();
    }

    public synchronized String start() {
        if (serving) {
            return said;
        }
        ServeConfig config = ServeConfig.defaults().withPort(port);
        if (beyondThisMachine) {
            config = config.withBind("0.0.0.0").withToken(AccessToken.generate(new SecureRandom()));
        }
        try {
            FoxgloveServer server = live.start(config); // viewers may switch options: `options --connect`
            serving = true;
            said = "Serving to viewers: " + String.join("  ", server.urls());
        } catch (IllegalArgumentException e) {
            said = "Cannot serve: " + e.getMessage();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            said = "Cannot serve: interrupted";
        } catch (Exception e) { // the bind's own exception, e.g. the port in use
            said = "Cannot serve on port " + port + ": " + e.getMessage();
        }
        return said;
    }

    public synchronized String stop() {
        if (serving) {
            live.stop();
            serving = false;
            said = "Stopped serving; the viewers were disconnected.";
        }
        return said;
    }

    /** What the last start or stop came to. */
    public synchronized String said() {
        return said;
    }

    public synchronized Optional<FoxgloveServer> server() {
        return serving ? live.server() : Optional.empty();
    }

    @Override
    public synchronized void close() {
        stop();
    }
}
