package touchline.transport;

/**
 * A stream one can subscribe to: the console's {@link LiveStream} or its {@link ReplayStream}.
 * What may take either (the live server, which serves the field or, with {@code serve
 * --replay}, a recording) takes this and is told which; what must never see a replay takes
 * the {@link LiveStream} itself.
 */
public interface EnvelopeSource {

    /** Delivers every envelope of the stream to {@code sink} until the returned handle is closed. */
    AutoCloseable subscribe(EnvelopeSink sink);
}
