/**
 * The options feature: per robot the debug options it offers, switched through match mode ({@code OptionsView}).
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.options;
