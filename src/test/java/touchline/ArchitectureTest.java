package touchline;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import org.junit.jupiter.api.Test;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;

/**
 * The dependency rule of style.md and docs/architecture.md, written down whole: every package
 * of the product belongs to a layer (protocol → game → transport → model/record → app →
 * faces), a layer is used only by the layers above it, protocol and game are pure, and JavaFX
 * stays in the window's code. The benchmarks (src/bench) are not in target/classes at all.
 */
class ArchitectureTest {

    private static final String[] LAYERS = {"touchline.proto..", "touchline.protocol..", "touchline.security..",
            "touchline.game..", "touchline.transport..", "touchline.model..", "touchline.record..", "touchline.app..", "touchline.serve..",
            "touchline.ui..", "touchline.cli.."};

    // Only our compiled classes: scanning every jar on the class path for the package is slow.
    private final JavaClasses classes = new ClassFileImporter()
            .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
            .importPath(java.nio.file.Path.of("target/classes"));

    @Test
    void everyPackageBelongsToALayer() {
        // a new package must be placed in the rule below (and in docs/architecture.md)
        classes().should().resideInAnyPackage(LAYERS).check(classes);
    }

    @Test
    void eachLayerIsUsedOnlyByTheLayersAboveIt() {
        layeredArchitecture().consideringOnlyDependenciesInLayers()
                .layer("Protocol").definedBy("touchline.proto..", "touchline.protocol..")
                .layer("Security").definedBy("touchline.security..")
                .layer("Game").definedBy("touchline.game..")
                .layer("Transport").definedBy("touchline.transport..")
                .layer("Model").definedBy("touchline.model..")
                .layer("Record").definedBy("touchline.record..")
                .layer("App").definedBy("touchline.app..")
                .layer("Serve").definedBy("touchline.serve..")
                .layer("Faces").definedBy("touchline.ui..", "touchline.cli..")
                .whereLayer("Faces").mayNotBeAccessedByAnyLayer()
                .whereLayer("App").mayOnlyBeAccessedByLayers("Faces")
                // the live server is a runtime under the core, like the recorder: app.LiveServing starts it
                .whereLayer("Serve").mayOnlyBeAccessedByLayers("App", "Faces")
                .whereLayer("Record").mayOnlyBeAccessedByLayers("App", "Serve", "Faces")
                .whereLayer("Model").mayOnlyBeAccessedByLayers("App", "Faces")
                .whereLayer("Transport").mayOnlyBeAccessedByLayers("Model", "Record", "App", "Serve", "Faces")
                // the GameController's runtime and match mode live in app.game; the game library is pure
                .whereLayer("Game").mayOnlyBeAccessedByLayers("App", "Faces")
                // keys and tags: below the transport (which tags and checks), never above the faces
                .whereLayer("Security").mayOnlyBeAccessedByLayers("Transport", "Model", "Record", "App", "Serve", "Faces")
                .whereLayer("Protocol").mayOnlyBeAccessedByLayers("Game", "Transport", "Model", "Record", "App", "Serve",
                        "Faces")
                .check(classes);
    }

    @Test
    void tagCodeIsPureOnlyKeyFilesTouchTheDisk() {
        // the tag, trailer and replay logic are pure like the protocol; the key directory does I/O
        noClasses().that().resideInAPackage("touchline.security..")
                .and().haveNameNotMatching("touchline\\.security\\.KeyDir(\\$.*)?")
                .should().dependOnClassesThat().resideInAnyPackage("java.nio.file..", "java.net..", "io.netty..",
                        "touchline.transport..", "touchline.model..", "touchline.app..")
                .check(classes);
        noClasses().that().resideInAPackage("touchline.security..")
                .should().dependOnClassesThat().resideInAnyPackage("touchline.transport..", "touchline.model..",
                        "touchline.record..", "touchline.app..", "touchline.serve..", "touchline.ui..", "touchline.cli..")
                .check(classes);
    }

    @Test
    void modelAndRecordDoNotKnowEachOther() {
        noClasses().that().resideInAPackage("touchline.model..")
                .should().dependOnClassesThat().resideInAPackage("touchline.record..").check(classes);
        noClasses().that().resideInAPackage("touchline.record..")
                .should().dependOnClassesThat().resideInAPackage("touchline.model..").check(classes);
    }

    @Test
    void protocolAndGameHaveNoThreadsFilesOrSockets() {
        noClasses().that().resideInAnyPackage("touchline.protocol..", "touchline.game..")
                .should().dependOnClassesThat().resideInAnyPackage("java.io..", "java.nio.file..", "java.nio.channels..",
                        "java.net..", "io.netty..", "org.zeromq..")
                .orShould().dependOnClassesThat().haveFullyQualifiedName("java.lang.Thread")
                .orShould().dependOnClassesThat().haveNameMatching("java\\.util\\.concurrent\\.(Executor.*|ScheduledExecutorService|ThreadPoolExecutor|CompletableFuture)")
                .check(classes);
    }

    @Test
    void javaFxOnlyInTheWindowAndTheCommandsThatOpenIt() {
        noClasses().that().resideOutsideOfPackages("touchline.ui..")
                .and().doNotHaveFullyQualifiedName("touchline.cli.ConsoleCommand")
                .and().doNotHaveFullyQualifiedName("touchline.cli.ScreenshotsCommand")
                .and().doNotHaveFullyQualifiedName("touchline.cli.FxThread")
                .should().dependOnClassesThat().resideInAnyPackage("javafx..")
                .check(classes);
    }

    /**
     * One clock: the wall clock is read only by {@code app.SystemClock}, which the console and
     * the commands without a console make once and hand down through constructors.
     */
    @Test
    void theWallClockIsReadOnlyByTheSystemClock() {
        noClasses().that().doNotBelongToAnyOf(touchline.app.SystemClock.class)
                .should().callMethod(System.class, "currentTimeMillis")
                .orShould().callMethod(java.time.Instant.class, "now")
                .orShould().callMethod(java.time.LocalDateTime.class, "now")
                .orShould().callMethod(java.time.LocalDate.class, "now")
                .orShould().callMethod(java.time.LocalTime.class, "now")
                .orShould().callMethod(java.time.ZonedDateTime.class, "now")
                .orShould().callMethod(java.time.OffsetDateTime.class, "now")
                .orShould().callMethod(java.time.Clock.class, "systemUTC")
                .orShould().callMethod(java.time.Clock.class, "systemDefaultZone")
                .orShould().callConstructor(java.util.Date.class)
                .check(classes);
    }

    /**
     * {@code System.nanoTime()} is no time source for data, models or the game: besides the
     * SystemClock only code that measures a duration or bounds its own wait reads it (a command
     * waiting for its deadline, the frame pulse timing a view, the recorder's disk thread aging
     * its open chunk, the GameController sender's real-time schedule, the remote viewer's
     * handshake timeout and silence watchdog); the NAO link and camera stream take the console's
     * monotonic clock.
     */
    @Test
    void theMonotonicClockOnlyMeasuresDurationsOutsideTheSystemClock() {
        noClasses().that().doNotBelongToAnyOf(touchline.app.SystemClock.class, touchline.ui.frame.FramePulse.class,
                        touchline.record.McapWriter.class, touchline.transport.gamecontroller.GcSender.class)
                .and().doNotHaveFullyQualifiedName("touchline.record.BackgroundFiles")
                .and().doNotHaveFullyQualifiedName("touchline.transport.remote.FoxgloveSession")
                .and().resideOutsideOfPackage("touchline.cli..")
                .should().callMethod(System.class, "nanoTime")
                .check(classes);
    }

    /**
     * The NAO link and the GameController runtime run on the clocks they are handed (the
     * console's, a test's fake): they neither read the system's time, not even to measure a
     * duration, nor make a clock of their own.
     */
    @Test
    void theNaoLinkAndTheGameRuntimeAreHandedTheirClocks() {
        noClasses().that().resideInAnyPackage("touchline.transport.nao..", "touchline.app.game..")
                .should().callMethod(System.class, "nanoTime")
                .orShould().callMethod(System.class, "currentTimeMillis")
                .orShould().callMethod(java.time.Instant.class, "now")
                .orShould().callConstructor(touchline.app.SystemClock.class)
                .check(classes);
    }

    /**
     * Nothing starts a thread in a constructor: making an object starts nothing, its owner (the
     * composition root, {@code Console}) calls its {@code start()}. A constructor calls no
     * {@code Thread.start}, no {@code start()} of any kind, hands no task to an executor (JDK or
     * Netty) nor prestarts its threads, and binds or connects no Netty bootstrap (which starts the
     * event loops); a lambda it makes, run later, may.
     */
    @Test
    void noConstructorStartsAThread() {
        com.tngtech.archunit.lang.syntax.ArchRuleDefinition.constructors()
                .should(new com.tngtech.archunit.lang.ArchCondition<com.tngtech.archunit.core.domain.JavaConstructor>(
                        "start no thread") {
                    @Override
                    public void check(com.tngtech.archunit.core.domain.JavaConstructor constructor,
                                      com.tngtech.archunit.lang.ConditionEvents events) {
                        for (var call : constructor.getMethodCallsFromSelf()) {
                            if (!call.isDeclaredInLambda() && startsAThread(call.getTargetOwner(), call.getName())) {
                                events.add(com.tngtech.archunit.lang.SimpleConditionEvent.violated(constructor,
                                        constructor.getFullName() + " calls " + call.getTarget().getFullName()
                                                + " in " + call.getSourceCodeLocation()));
                            }
                        }
                    }
                })
                .allowEmptyShould(false)
                .check(classes);
    }

    /**
     * Matched by the call's owner <em>name</em>, not its resolved type: the importer does not
     * resolve JDK and Netty classes (archunit.properties), so a type check would not see an
     * executor's or a bootstrap's call at all.
     */
    private static boolean startsAThread(com.tngtech.archunit.core.domain.JavaClass owner, String method) {
        String name = owner.getName();
        if (method.equals("start") && (name.startsWith("java.lang.Thread") || owner.getPackageName().startsWith("touchline"))) {
            return true;
        }
        if (name.matches("io\\.netty\\.bootstrap\\.\\w*Bootstrap") && (method.equals("bind") || method.equals("connect"))) {
            return true; // binding or connecting starts the group's event loops
        }
        boolean executor = EXECUTOR_NAMES.matcher(name).matches()
                || owner.isAssignableTo(java.util.concurrent.Executor.class);
        return executor && (method.equals("execute") || method.equals("submit") || method.startsWith("schedule")
                || method.startsWith("invoke") || method.startsWith("prestart"));
    }

    /** The JDK's executors and Netty's event executors and loops, by name. */
    private static final java.util.regex.Pattern EXECUTOR_NAMES = java.util.regex.Pattern.compile(
            "java\\.util\\.concurrent\\.(Executor|ExecutorService|ScheduledExecutorService|AbstractExecutorService"
                    + "|ThreadPoolExecutor|ScheduledThreadPoolExecutor|ForkJoinPool)"
                    + "|io\\.netty\\.util\\.concurrent\\.\\w*EventExecutor\\w*|io\\.netty\\.channel\\.\\w*EventLoop\\w*");

    /** The benchmarks use no harness: none is on the class path the product is built and tested with. */
    @Test
    void noBenchmarkHarnessOnTheClassPath() {
        org.junit.jupiter.api.Assertions.assertThrows(ClassNotFoundException.class,
                () -> Class.forName("org.openjdk.jmh.annotations.Benchmark"), "JMH is on the class path");
    }

    @Test
    void noMainMethodOrExitOutsideTheLaunchers() {
        noClasses().that().doNotHaveFullyQualifiedName("touchline.cli.Main")
                .and().doNotHaveFullyQualifiedName("touchline.ui.Launcher")
                .should().callMethod(System.class, "exit", int.class)
                .check(classes);
    }

    @Test
    void protocolDependsOnNothingOfOurs() {
        noClasses().that().resideInAPackage("touchline.protocol..")
                .should().dependOnClassesThat().resideInAnyPackage("touchline.transport..", "touchline.model..",
                        "touchline.record..", "touchline.app..", "touchline.cli..", "touchline.ui..", "touchline.game..",
                        "touchline.nao..")
                .check(classes);
    }

    @Test
    void protocolHasNoSocketsThreadsOrJavaFx() {
        noClasses().that().resideInAPackage("touchline.protocol..")
                .should().dependOnClassesThat().resideInAnyPackage("io.netty..", "org.zeromq..", "javafx..", "java.net..")
                .check(classes);
    }

    @Test
    void transportDoesNotDependOnModelOrAbove() {
        noClasses().that().resideInAPackage("touchline.transport..")
                .should().dependOnClassesThat().resideInAnyPackage("touchline.model..", "touchline.record..",
                        "touchline.app..", "touchline.cli..", "touchline.ui..")
                .check(classes);
    }

    @Test
    void nothingBelowTheFacesDependsOnUiOrCli() {
        noClasses().that().resideOutsideOfPackages("touchline.ui..", "touchline.cli..")
                .should().dependOnClassesThat().resideInAnyPackage("touchline.ui..", "touchline.cli..")
                .check(classes);
    }

    @Test
    void theFrameMachineryAndTheDrawingKnowNoWindowAndNoFeature() {
        // ui.frame and ui.render are shared by every feature: they are handed narrow services and
        // small interfaces (the status a pulse refreshes, the views it pulls), never the window's types
        noClasses().that().resideInAnyPackage("touchline.ui.frame..", "touchline.ui.render..")
                .should().dependOnClassesThat().resideInAnyPackage("touchline.ui.window..", "touchline.ui.robots..",
                        "touchline.ui.options..", "touchline.ui.consoles..", "touchline.ui.plots..",
                        "touchline.ui.field..", "touchline.ui.replay..", "touchline.ui.referee..", "touchline.ui.nao..",
                        "touchline.ui.viewers..", "touchline.ui.ros2..")
                .check(classes);
    }

    @Test
    void theLiveServerIsAFaceOverTheStream() {
        noClasses().that().resideInAPackage("touchline.serve..")
                .should().dependOnClassesThat().resideInAnyPackage("touchline.model..", "touchline.app..",
                        "touchline.cli..", "touchline.ui..")
                .check(classes);
        noClasses().that().resideInAnyPackage("touchline.protocol..", "touchline.transport..", "touchline.model..",
                        "touchline.record..", "touchline.game..")
                .should().dependOnClassesThat().resideInAPackage("touchline.serve..")
                .check(classes);
    }

    /**
     * Issue 38: live and replay apart by construction. A replay has its own stream, and the
     * type never reaches what acts on the field: no sender or transport, no match mode or
     * referee, no recorder or live server, no options switch, budget guard or game-state
     * listener may even name it; of the core only the composition root and the replay use case
     * (which wire the read models to it) do. A sender takes an {@code EnvelopeSink}, which
     * {@code ReplayStream} is not. (The live server takes an {@code EnvelopeSource} and is told
     * which: {@code serve --replay} serves a recording instead of the field, with no option
     * switches offered.)
     */
    @Test
    void theReplayStreamNeverReachesWhatActsOnTheField() {
        noClasses().that().resideOutsideOfPackages("touchline.app", "touchline.ui..", "touchline.cli..")
                .and().doNotBelongToAnyOf(touchline.transport.ReplayStream.class)
                .should().dependOnClassesThat().belongToAnyOf(touchline.transport.ReplayStream.class)
                .check(classes);
        noClasses().that().haveNameMatching("touchline\\.app\\.(ReportedGameState|RemoteGameState|NaoSession|NaoCamera"
                        + "|LiveSwitch|WantedOptionsFile)(\\$.*)?")
                .should().dependOnClassesThat().belongToAnyOf(touchline.transport.ReplayStream.class)
                .check(classes);
        noClasses().that().haveNameMatching("touchline\\.(ui|cli)\\..*(Record|Options|GameController|Referee|Nao).*")
                .should().dependOnClassesThat().belongToAnyOf(touchline.transport.ReplayStream.class)
                .check(classes);
    }

    @Test
    void uiDoesNotTalkToSocketsDirectly() {
        noClasses().that().resideInAPackage("touchline.ui..")
                .should().dependOnClassesThat().resideInAnyPackage("io.netty..", "org.zeromq..")
                .allowEmptyShould(true)
                .check(classes);
    }

    @Test
    void modelAndBelowNeverTouchJavaFx() {
        noClasses().that().resideInAnyPackage("touchline.protocol..", "touchline.transport..", "touchline.model..",
                        "touchline.record..", "touchline.app..", "touchline.game..", "touchline.serve..")
                .should().dependOnClassesThat().resideInAnyPackage("javafx..")
                .check(classes);
    }

    /**
     * The places that compose: they make the {@code app.Console} (the composition root) and hand
     * its services on. The window's entry point and the window itself; each CLI command that runs a
     * console, since every command is its own process's entry point with its own configuration
     * (the port, keys, a remote URL), and the two option mixins that start one for them.
     */
    static final java.util.Set<String> COMPOSERS = java.util.Set.of(
            "touchline.ui.TouchlineApp", "touchline.ui.window.ConsoleWindow",
            "touchline.cli.ConsoleCommand", "touchline.cli.ScreenshotsCommand", "touchline.cli.ListenCommand",
            "touchline.cli.OptionsCommand", "touchline.cli.StreamCommand", "touchline.cli.NaoCommand",
            "touchline.cli.RecordCommand", "touchline.cli.ServeCommand", "touchline.cli.UdpOptions",
            "touchline.cli.RemoteOptions");

    /**
     * A view or command takes the one or two use-case services it needs ({@code LiveField},
     * {@code Referee}, {@code Replays}, ...), never the composition root: only the composers
     * above know {@code Console}.
     */
    @Test
    void facesTakeServicesNotTheConsole() {
        noClasses().that().resideInAnyPackage("touchline.ui..", "touchline.cli..", "touchline.serve..")
                .and(com.tngtech.archunit.base.DescribedPredicate.describe("not a composer",
                        (com.tngtech.archunit.core.domain.JavaClass c) -> !COMPOSERS.contains(
                                c.getEnclosingClass().map(com.tngtech.archunit.core.domain.JavaClass::getName)
                                        .orElse(c.getName()))))
                .should().dependOnClassesThat().haveFullyQualifiedName("touchline.app.Console")
                .check(classes);
    }

    /**
     * What the faces (ui, cli) and the live server may take from the transport: the stream's
     * values and configuration, never a socket owner. Everything else they do through the
     * application core's use cases ({@code LiveField.port()}, {@code transportCounts()},
     * {@code openStream()}, ...). docs/architecture.md lists the same.
     */
    static final java.util.Set<String> TRANSPORT_VALUES_FOR_FACES = java.util.Set.of(
            // the Envelope stream and its values
            "touchline.transport.Envelope", "touchline.transport.Direction", "touchline.transport.Channel",
            "touchline.transport.Origin", "touchline.transport.EnvelopeBus", "touchline.transport.EnvelopeSink",
            "touchline.transport.LiveStream", "touchline.transport.ReplayStream", "touchline.transport.EnvelopeSource",
            "touchline.transport.MicrosClock", "touchline.transport.SendResult", "touchline.transport.SendResult$Outcome",
            // configuration and descriptions handed to the core
            "touchline.transport.UdpConfig", "touchline.transport.UdpBackend", "touchline.transport.UdpBackend$Kind",
            "touchline.transport.PeerText", "touchline.transport.HostPort",
            // the one reader of the game state an envelope carries (pure; the live server's /gc/state)
            "touchline.transport.GameStateReader",
            // a reliable stream the core opened (LiveField.openStream)
            "touchline.transport.ReliableSession",
            // the GameController's configuration and the tallies its views read (liveness, bad packets, monitors)
            "touchline.transport.gamecontroller.GcConfig", "touchline.transport.gamecontroller.GcProfile",
            "touchline.transport.gamecontroller.RobotLiveness", "touchline.transport.gamecontroller.RobotLiveness$RobotKey",
            "touchline.transport.gamecontroller.RobotLiveness$Status", "touchline.transport.gamecontroller.BadPackets",
            "touchline.transport.gamecontroller.BadPackets$Tally", "touchline.transport.gamecontroller.MonitorStats",
            // viewing another Touchline: its status, and the certificate to trust
            "touchline.transport.remote.RemoteStatus", "touchline.transport.remote.RemoteStatus$State",
            "touchline.transport.remote.RemoteTrust",
            // the robots behind Foxglove bridges: their status, parameters and service answers (the bridges are the core's: RosBridges)
            "touchline.transport.remote.BridgeStatus", "touchline.transport.remote.Bridge$Parameter",
            "touchline.transport.remote.ServiceAnswer",
            // the NAO's values: what a face asks of a NaoSession/NaoCamera and what it answers (never
            // NaoLink, NaoCameraStream or NaoConnection: the link and the camera are the core's)
            "touchline.transport.nao.NaoCall", "touchline.transport.nao.CallOutcome",
            "touchline.transport.nao.CallOutcome$Value", "touchline.transport.nao.CallOutcome$Done",
            "touchline.transport.nao.CallOutcome$Failed", "touchline.transport.nao.CallOutcome$TimedOut",
            "touchline.transport.nao.CallOutcome$Lost", "touchline.transport.nao.CallOutcome$HeldBack",
            "touchline.transport.nao.CallOutcome$Superseded", "touchline.transport.nao.SequenceOutcome",
            "touchline.transport.nao.ConnectionState", "touchline.transport.nao.CameraSettings",
            "touchline.transport.nao.WalkInput", "touchline.transport.nao.NaoLinkConfig",
            "touchline.transport.nao.NaoClientKeys");

    @Test
    void facesReachTheTransportOnlyThroughTheCore() {
        noClasses().that().resideInAnyPackage("touchline.ui..", "touchline.cli..", "touchline.serve..")
                .should().dependOnClassesThat(com.tngtech.archunit.base.DescribedPredicate.describe(
                        "transport classes other than the stream's values", (com.tngtech.archunit.core.domain.JavaClass c) ->
                                c.getPackageName().startsWith("touchline.transport")
                                && !TRANSPORT_VALUES_FOR_FACES.contains(c.getName())))
                .check(classes);
    }
}
