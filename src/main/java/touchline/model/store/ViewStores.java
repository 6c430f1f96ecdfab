package touchline.model.store;

import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

/**
 * The bounded stores the views read, fed together from the Envelope stream on the network
 * thread. Subscribe this one sink to the bus; views pull from the stores once per frame.
 */
public final class ViewStores implements EnvelopeSink {

    private final TextLog text;
    private final PlotStore plots;
    private final LatestValues latest = new LatestValues();
    private final NetworkLog network;

    public ViewStores(long originMicros) {
        this(TextLog.DEFAULT_CAPACITY, PlotStore.DEFAULT_POINTS, NetworkLog.DEFAULT_CAPACITY, originMicros);
    }

    public ViewStores(int textLines, int plotPoints, int networkEnvelopes, long originMicros) {
        this.text = new TextLog(textLines);
        this.plots = new PlotStore(plotPoints, originMicros);
        this.network = new NetworkLog(networkEnvelopes);
    }

    @Override
    public void accept(Envelope e) {
        network.accept(e);
        text.accept(e);
        plots.accept(e);
        latest.accept(e);
    }

    public TextLog text() { return text; }
    public PlotStore plots() { return plots; }
    public LatestValues latest() { return latest; }
    public NetworkLog network() { return network; }
}
