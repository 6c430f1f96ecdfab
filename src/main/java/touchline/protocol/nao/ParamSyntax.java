package touchline.protocol.nao;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.regex.Pattern;

/**
 * Reads one typed NAOqi call parameter from the text a user types (CLI argument or the
 * method browser's entry field): {@code 42} is an int, {@code 0.5}, {@code -1.2} or
 * {@code 3f} a float, {@code true}/{@code false} a bool, {@code [a, 1, [0.5]]} a list,
 * {@code "42"} a quoted string; anything else is taken as a string verbatim, so
 * {@code nao call HOST ALTextToSpeech.say hello world} needs no quotes for plain text.
 * Malformed lists give a {@link IllegalArgumentException} whose message points at the column.
 * The text may come from anywhere (a pasted file), so lists nest at most {@link #MAX_DEPTH}
 * deep and every pattern runs in linear time.
 */
public final class ParamSyntax {

    /** Lists inside lists, at most; NAOqi values nest a few levels. */
    public static final int MAX_DEPTH = 32;

    // Possessive quantifiers: "\\d+\\.?\\d*" tried every split of a long run of digits before
    // failing (60 000 digits then 'x': 57 s).
    private static final Pattern INT = Pattern.compile("[+-]?+\\d++");
    private static final Pattern FLOAT = Pattern.compile("[+-]?+(\\d++(\\.\\d*+)?+|\\.\\d++)([eE][+-]?+\\d++)?+[fF]?+");

    private final String text;
    private int pos;
    private int depth;

    private ParamSyntax(String text) {
        this.text = text;
    }

    public static Object parse(String text) {
        String t = text.strip();
        if (t.startsWith("[") || t.startsWith("\"")) {
            ParamSyntax p = new ParamSyntax(t);
            Object v = p.value();
            p.skipSpace();
            if (p.pos != t.length()) {
                throw p.error("unexpected text after the value");
            }
            return v;
        }
        Object scalar = scalar(t);
        return scalar != null ? scalar : text;
    }

    private static Object scalar(String t) {
        if (t.equals("true") || t.equals("false")) {
            return Boolean.valueOf(t);
        }
        if (INT.matcher(t).matches()) {
            try {
                return Long.parseLong(t);
            } catch (NumberFormatException e) {
                return null;
            }
        }
        if (FLOAT.matcher(t).matches()) {
            return Float.parseFloat(t.endsWith("f") || t.endsWith("F") ? t.substring(0, t.length() - 1) : t);
        }
        return null;
    }

    private Object value() {
        skipSpace();
        if (pos >= text.length()) {
            throw error("value expected");
        }
        char c = text.charAt(pos);
        if (c == '[') {
            return list();
        }
        if (c == '"') {
            return quoted();
        }
        int start = pos;
        while (pos < text.length() && text.charAt(pos) != ',' && text.charAt(pos) != ']') {
            pos++;
        }
        String word = text.substring(start, pos).strip();
        if (word.isEmpty()) {
            throw error("value expected");
        }
        Object scalar = scalar(word);
        return scalar != null ? scalar : word;
    }

    private List<Object> list() {
        if (++depth > MAX_DEPTH) {
            throw error("lists nested deeper than " + MAX_DEPTH + " levels");
        }
        pos++; // '['
        List<Object> out = new ArrayList<>();
        skipSpace();
        if (pos < text.length() && text.charAt(pos) == ']') {
            pos++;
            depth--;
            return Collections.unmodifiableList(out);
        }
        while (true) {
            out.add(value());
            skipSpace();
            if (pos >= text.length()) {
                throw error("missing ']'");
            }
            char c = text.charAt(pos++);
            if (c == ']') {
                depth--;
                return Collections.unmodifiableList(out);
            }
            if (c != ',') {
                throw error("',' or ']' expected");
            }
        }
    }

    private String quoted() {
        pos++; // '"'
        StringBuilder sb = new StringBuilder();
        while (pos < text.length()) {
            char c = text.charAt(pos++);
            if (c == '"') {
                return sb.toString();
            }
            if (c == '\\' && pos < text.length()) {
                c = text.charAt(pos++);
            }
            sb.append(c);
        }
        throw error("missing closing '\"'");
    }

    private void skipSpace() {
        while (pos < text.length() && Character.isWhitespace(text.charAt(pos))) {
            pos++;
        }
    }

    private IllegalArgumentException error(String what) {
        return new IllegalArgumentException(what + " at column " + (pos + 1) + " of: " + text);
    }
}
