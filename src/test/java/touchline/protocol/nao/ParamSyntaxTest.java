package touchline.protocol.nao;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ParamSyntaxTest {

    @Test
    void scalars() {
        assertEquals(42L, ParamSyntax.parse("42"));
        assertEquals(-3L, ParamSyntax.parse("-3"));
        assertEquals(0.5f, ParamSyntax.parse("0.5"));
        assertEquals(-1.25f, ParamSyntax.parse("-1.25"));
        assertEquals(3f, ParamSyntax.parse("3f"));
        assertEquals(true, ParamSyntax.parse("true"));
        assertEquals("hello world", ParamSyntax.parse("hello world"));
        assertEquals("42", ParamSyntax.parse("\"42\""));
        assertEquals("Stand", ParamSyntax.parse("Stand"));
    }

    @Test
    void lists() {
        assertEquals(List.of("HeadYaw", List.of(0.5f, 1L), List.of(), "a b"),
                ParamSyntax.parse("[HeadYaw, [0.5, 1], [], \"a b\"]"));
    }

    @Test
    void malformedListsSayWhere() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ParamSyntax.parse("[1, 2"));
        assertTrue(e.getMessage().contains("column"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> ParamSyntax.parse("[1,,2]"));
        assertThrows(IllegalArgumentException.class, () -> ParamSyntax.parse("\"open"));
        assertThrows(IllegalArgumentException.class, () -> ParamSyntax.parse("[1] x"));
    }

    @Test
    void listsNestDeeperThanTheLimitAreAnErrorNotAStackOverflow() {
        String nested = "[".repeat(ParamSyntax.MAX_DEPTH) + "1" + "]".repeat(ParamSyntax.MAX_DEPTH);
        Object v = ParamSyntax.parse(nested);
        for (int i = 0; i < ParamSyntax.MAX_DEPTH; i++) {
            v = ((List<?>) v).get(0);
        }
        assertEquals(1L, v, "the limit itself is allowed");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ParamSyntax.parse("[".repeat(2000)));
        assertTrue(e.getMessage().startsWith("lists nested deeper than " + ParamSyntax.MAX_DEPTH + " levels at column "
                + (ParamSyntax.MAX_DEPTH + 1)), e.getMessage());
        // siblings do not add up to depth
        assertEquals(40, ((List<?>) ParamSyntax.parse("[" + "[1],".repeat(39) + "[1]]")).size());
    }

    @Test
    @Timeout(value = 10, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD) // a guard only: the assertions below are the test
    void aLongRunOfDigitsThatIsNoNumberIsReadAsTextInOnePass() {
        String word = "7".repeat(60_000) + "x";
        assertEquals(word, ParamSyntax.parse(word));
        assertEquals(List.of(word), ParamSyntax.parse("[" + word + "]"));
        assertEquals(1.5e3f, ParamSyntax.parse("1.5e3f"));
        assertEquals(1f, ParamSyntax.parse("1."));
        assertEquals(0.25f, ParamSyntax.parse("+.25"));
        assertEquals("1e", ParamSyntax.parse("1e"));
    }
}
