package touchline.serve;

import touchline.transport.Envelope;

/** How a robot channel's envelopes become the bytes a viewer receives. */
interface ChannelPayloads {

    byte[] payload(Envelope e);
}
