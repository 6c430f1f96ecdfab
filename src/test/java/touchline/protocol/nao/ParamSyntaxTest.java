package touchline.protocol.nao;

import org.junit.jupiter.api.Test;

import java.util.List;

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
}
