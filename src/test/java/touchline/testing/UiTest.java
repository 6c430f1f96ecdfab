package touchline.testing;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.extension.ExtendWith;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * A test class of the real console window: tagged {@code ui} (the group the build runs with
 * Monocle, headless), and every field of type {@link touchline.ui.window.ConsoleWindowFixture} is a
 * fresh window before each test, on a layout directory of its own, closed after each test (after
 * the class's own {@code @AfterEach}). A class that opens its windows itself (another
 * configuration, two windows in one test) declares none and is only tagged.
 */
@Target(ElementType.TYPE)
@Retention(RetentionPolicy.RUNTIME)
@Tag("ui")
@ExtendWith(ConsoleWindowExtension.class)
public @interface UiTest {
}
