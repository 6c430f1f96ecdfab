package touchline.serve;

/**
 * One viewer's subscription to one channel, under the id the viewer chose. Messages pending
 * for it are dropped once it ends, even when they were queued a moment before.
 */
final class Subscription {

    private final Viewer viewer;
    private final int id;
    private final ServedChannel channel;
    private volatile boolean active = true;

    Subscription(Viewer viewer, int id, ServedChannel channel) {
        this.viewer = viewer;
        this.id = id;
        this.channel = channel;
    }

    Viewer viewer() {
        return viewer;
    }

    int id() {
        return id;
    }

    ServedChannel channel() {
        return channel;
    }

    boolean active() {
        return active;
    }

    void end() {
        active = false;
        channel.remove(this);
    }
}
