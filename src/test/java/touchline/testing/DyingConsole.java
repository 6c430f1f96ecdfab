package touchline.testing;

import java.lang.reflect.Field;

/**
 * A stand-in for a console JVM that dies, for the launcher's tests: {@code crash} makes the JVM
 * itself fail (a write to address 0: SIGSEGV, the JVM writes its crash log and aborts), a
 * number ends it with that exit code.
 */
public final class DyingConsole {

    private DyingConsole() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length == 1 && args[0].equals("crash")) {
            Field f = sun.misc.Unsafe.class.getDeclaredField("theUnsafe");
            f.setAccessible(true);
            ((sun.misc.Unsafe) f.get(null)).putAddress(0L, 42L);
        }
        System.exit(Integer.parseInt(args[0]));
    }
}
