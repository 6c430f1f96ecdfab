/**
 * The NAO tab ({@code NaoView}), bound to the core's {@code NaoViewModel}.
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.nao;
