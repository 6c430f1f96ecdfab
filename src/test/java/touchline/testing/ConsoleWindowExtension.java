package touchline.testing;

import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;
import touchline.ui.window.ConsoleWindowFixture;

import java.io.IOException;
import java.lang.reflect.Field;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * What {@link UiTest} does before and after each test: opens a window per
 * {@link ConsoleWindowFixture} field of the test instance (its layouts in a temporary directory)
 * and closes it, and the directory, afterwards.
 */
public final class ConsoleWindowExtension implements BeforeEachCallback, AfterEachCallback {

    private static final ExtensionContext.Namespace WINDOWS = ExtensionContext.Namespace.create(ConsoleWindowExtension.class);

    private record Opened(ConsoleWindowFixture window, Path layouts) { }

    @Override
    public void beforeEach(ExtensionContext context) throws Exception {
        Object test = context.getRequiredTestInstance();
        List<Opened> opened = new ArrayList<>();
        context.getStore(WINDOWS).put(context.getUniqueId(), opened);
        for (Class<?> c = test.getClass(); c != Object.class; c = c.getSuperclass()) {
            for (Field f : c.getDeclaredFields()) {
                if (f.getType() == ConsoleWindowFixture.class && !java.lang.reflect.Modifier.isStatic(f.getModifiers())) {
                    Path layouts = Files.createTempDirectory("touchline-ui-layouts");
                    ConsoleWindowFixture window = new ConsoleWindowFixture(layouts);
                    opened.add(new Opened(window, layouts));
                    f.setAccessible(true);
                    f.set(test, window);
                }
            }
        }
    }

    @Override
    public void afterEach(ExtensionContext context) throws Exception {
        @SuppressWarnings("unchecked")
        List<Opened> opened = (List<Opened>) context.getStore(WINDOWS).remove(context.getUniqueId(), List.class);
        if (opened == null) {
            return;
        }
        Exception first = null;
        for (Opened o : opened) {
            try {
                o.window().close();
            } catch (Exception e) {
                if (first == null) {
                    first = e;
                } else {
                    first.addSuppressed(e);
                }
            }
            delete(o.layouts());
        }
        if (first != null) {
            throw first;
        }
    }

    private static void delete(Path dir) throws IOException {
        try (Stream<Path> paths = Files.walk(dir)) {
            for (Path p : paths.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        }
    }
}
