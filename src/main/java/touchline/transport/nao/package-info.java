/**
 * The ZeroMQ link to a NAO's {@code HAWActorRPC} module: {@code NaoLink} (one thread, {@code LinkLoop}, owns the
 * JeroMQ socket {@code NaoConnection}; calls are paced, dispatched and answered through {@code CallPacing}, {@code
 * CallDispatcher}, {@code PendingCalls}), its rules per method ({@code NaoLinkConfig}), high-level moves as call
 * sequences ({@code NaoMoves}), the connection state ({@code ConnectionWatch}, {@code ConnectionState}) and the
 * camera stream shared by every viewer ({@code NaoCameraStream}, {@code CameraFrame}, {@code CameraSettings}). NAO
 * traffic enters the Envelope stream through {@code NaoEnvelopeChannel}.
 * <p>
 * May depend on: protocol (protocol.nao), security (CURVE keys) and the transport layer's own types.
 */
package touchline.transport.nao;
