package touchline.protocol.gamecontroller;

/**
 * The identity every game-state format shares: its envelope kind, version and exact size.
 * Subclasses supply only the layout.
 */
abstract class FixedSizeFormat implements GameStateFormat {

    private final String kind;
    private final int version;
    private final int size;

    FixedSizeFormat(String kind, int version, int size) {
        this.kind = kind;
        this.version = version;
        this.size = size;
    }

    @Override
    public final String kind() {
        return kind;
    }

    @Override
    public final int version() {
        return version;
    }

    @Override
    public final int size() {
        return size;
    }
}
