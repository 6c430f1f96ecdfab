/**
 * The bounded stores the views pull from once per frame, fed together from the Envelope stream ({@code
 * ViewStores}): the newest value of every option ({@code LatestValues}), plot history ({@code PlotStore}, {@code
 * FieldPlot}), the debug console's and the network console's logs ({@code TextLog}, {@code NetworkLog} on {@code
 * SequencedRing}).
 * <p>
 * May depend on: the model layer and what it may use (transport, security, protocol).
 */
package touchline.model.store;
