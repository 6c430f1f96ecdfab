/**
 * The frame machinery: once per frame ({@code FramePulse}, {@code FrameCap}) the change counter
 * ({@code ConsoleChanges}) is read and the open views pull ({@code View}, {@code ViewFrame}, {@code FrameContext});
 * {@code IdleWatch} restarts the frames after a quiet spell; {@code PacedText} paces changing labels;
 * a view's source bar and robot filter ({@code SourceBar}, {@code SourcedView}, {@code RobotFilter}).
 * <p>
 * May depend on: as ui, but no ui.window and no feature package (ArchitectureTest): the window hands
 * the pulse its views ({@code PulledView}) and status bar ({@code FrameStatus}); views hand narrow services.
 */
package touchline.ui.frame;
