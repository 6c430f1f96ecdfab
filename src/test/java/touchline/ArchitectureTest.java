package touchline;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import org.junit.jupiter.api.Test;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;

/** The dependency rule of style.md: protocol depends on nothing of ours; nothing depends on ui or cli. */
class ArchitectureTest {

    // Only our compiled classes: scanning every jar on the class path for the package is slow.
    private final JavaClasses classes = new ClassFileImporter()
            .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
            .importPath(java.nio.file.Path.of("target/classes"));

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
}
