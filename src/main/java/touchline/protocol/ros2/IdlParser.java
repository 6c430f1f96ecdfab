package touchline.protocol.ros2;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The {@code ros2idl} form: the IDL rosidl generates for each type ({@code module pkg { module
 * msg { struct Type { ... }; }; };}), sections separated by a line of {@code =} and
 * {@code IDL: pkg/msg/Type}. Read: modules, structs, members with their IDL types (the ROS
 * names {@code int8 … uint64} as well as {@code short}, {@code long long}, {@code octet}, ...),
 * {@code string<N>}, {@code sequence<T>}, {@code sequence<T, N>}, fixed arrays {@code T x[N]},
 * typedefs, constants (in a module {@code Type_Constants}, as rosidl writes them), annotations
 * ({@code @default}, {@code @verbatim}, ...) and {@code #include} lines read past. Enums,
 * unions and multi-dimensional arrays are refused.
 * Over 400 lines because it is one recursive-descent parser of that IDL subset: its rules call
 * each other and share one token cursor and the scope's typedefs; its tokenizer is the last part.
 */
final class IdlParser {

    private record Token(String text, int line, boolean literal) { }

    /**
     * A type with its shape, ready to become a field (also what a typedef names). A struct
     * reference keeps the names it may mean, innermost scope first, until every struct is known.
     */
    private record Alias(Primitive primitive, List<String> candidates, int line, Field.Shape shape, int bound,
                         int stringBound) {

        Alias shaped(Field.Shape s, int b) {
            return new Alias(primitive, candidates, line, s, b, stringBound);
        }
    }

    /** A member as declared, its struct type not yet resolved. */
    private record Member(String name, Alias type) { }

    private final java.util.Set<String> builtIn;
    private List<Token> tokens;
    private int at;

    /** {@code builtIn}: types a schema may name without defining them ({@code builtin_interfaces/msg/Time}). */
    IdlParser(java.util.Set<String> builtIn) {
        this.builtIn = builtIn;
    }
    private final Map<String, Alias> typedefs = new HashMap<>();
    private final Map<String, List<Member>> structs = new LinkedHashMap<>();
    private final Map<String, List<MessageType.Constant>> constants = new HashMap<>();

    Map<String, MessageType> parse(String text) throws DefinitionException {
        tokens = tokenize(text);
        at = 0;
        List<String> scope = new ArrayList<>();
        definitions(scope, false);
        Map<String, MessageType> types = new LinkedHashMap<>();
        for (Map.Entry<String, List<Member>> s : structs.entrySet()) {
            List<Field> fields = new ArrayList<>();
            for (Member m : s.getValue()) {
                Alias a = m.type();
                String typeName = null;
                if (a.primitive() == null) {
                    typeName = a.candidates().stream().filter(c -> structs.containsKey(c) || builtIn.contains(c))
                            .findFirst().orElse(null);
                    if (typeName == null) {
                        throw new DefinitionException(a.line(), "the type "
                                + a.candidates().get(0).replace("/", "::") + " of "
                                + m.name() + " is not defined in the schema");
                    }
                }
                fields.add(new Field(m.name(), a.primitive(), typeName, a.shape(), a.bound(), a.stringBound()));
            }
            types.put(s.getKey(), new MessageType(s.getKey(), fields, constants.getOrDefault(s.getKey(), List.of())));
        }
        return types;
    }

    // ---- grammar

    private void definitions(List<String> scope, boolean inModule) throws DefinitionException {
        while (at < tokens.size()) {
            skipAnnotations();
            Token t = next("a definition");
            switch (t.text()) {
                case "}" -> {
                    if (!inModule) {
                        throw new DefinitionException(t.line(), "'}' without a module to close");
                    }
                    expect(";");
                    return;
                }
                case ";" -> { }
                case "module" -> {
                    String name = identifier();
                    expect("{");
                    scope.add(name);
                    definitions(scope, true);
                    scope.remove(scope.size() - 1);
                }
                case "struct" -> struct(scope);
                case "typedef" -> typedef(scope);
                case "const" -> constant(scope);
                case "enum", "union" -> throw new DefinitionException(t.line(), t.text() + " types are not supported");
                default -> throw new DefinitionException(t.line(), "'" + MsgParser.cut(t.text())
                        + "' where a module, struct, typedef or const was expected");
            }
        }
        if (inModule) {
            throw new DefinitionException(lastLine(), "the schema ends inside a module ('}' missing)");
        }
    }

    private void struct(List<String> scope) throws DefinitionException {
        String name = identifier();
        String full = String.join("/", scope) + (scope.isEmpty() ? "" : "/") + name;
        if (peekIs(";")) {
            at++; // a forward declaration
            return;
        }
        expect("{");
        List<Member> fields = new ArrayList<>();
        while (true) {
            skipAnnotations();
            if (peekIs("}")) {
                at++;
                expect(";");
                break;
            }
            Alias type = typeSpec(scope);
            do {
                Token n = next("a member name");
                checkIdentifier(n);
                fields.add(new Member(n.text(), declarator(n.text(), type, n.line())));
            } while (nextIs(","));
            expect(";");
        }
        if (structs.containsKey(full)) {
            if (!sameShape(structs.get(full), fields)) {
                throw new DefinitionException(tokens.get(at - 1).line(), "the schema defines " + full + " twice, differently");
            }
            return;
        }
        structs.put(full, fields);
    }

    private static boolean sameShape(List<Member> a, List<Member> b) {
        if (a.size() != b.size()) {
            return false;
        }
        for (int i = 0; i < a.size(); i++) {
            Alias x = a.get(i).type();
            Alias y = b.get(i).type();
            if (!a.get(i).name().equals(b.get(i).name()) || x.shape() != y.shape() || x.primitive() != y.primitive()
                    || x.bound() != y.bound()) {
                return false;
            }
        }
        return true;
    }

    /** Declarator: a name, maybe with one {@code [N]}. */
    private Alias declarator(String name, Alias type, int line) throws DefinitionException {
        if (!peekIs("[")) {
            return type;
        }
        at++;
        Token n = next("an array length");
        int length = MsgParser.number(digits(n), n.line());
        expect("]");
        if (type.shape() != Field.Shape.SINGLE || peekIs("[")) {
            throw new DefinitionException(line, name + ": arrays of arrays are not supported");
        }
        return type.shaped(Field.Shape.FIXED_ARRAY, length);
    }

    private void typedef(List<String> scope) throws DefinitionException {
        Alias type = typeSpec(scope);
        Token n = next("a typedef name");
        checkIdentifier(n);
        Alias alias = declarator(n.text(), type, n.line());
        expect(";");
        typedefs.put(String.join("/", scope) + (scope.isEmpty() ? "" : "/") + n.text(), alias);
    }

    private void constant(List<String> scope) throws DefinitionException {
        Alias type = typeSpec(scope);
        String name = identifier();
        expect("=");
        StringBuilder value = new StringBuilder();
        while (!peekIs(";")) {
            Token v = next("the constant's value");
            value.append(v.literal() ? "\"" + v.text() + "\"" : v.text());
        }
        at++;
        if (type.primitive() == null || type.shape() != Field.Shape.SINGLE) {
            return; // not a constant ROS writes; nothing on the wire either way
        }
        String module = scope.isEmpty() ? "" : scope.get(scope.size() - 1);
        String owner = String.join("/", scope.subList(0, Math.max(0, scope.size() - 1))) + "/"
                + (module.endsWith("_Constants") ? module.substring(0, module.length() - "_Constants".length()) : module);
        constants.computeIfAbsent(owner, k -> new ArrayList<>()).add(new MessageType.Constant(type.primitive(), name,
                value.toString()));
    }

    private Alias typeSpec(List<String> scope) throws DefinitionException {
        Token t = next("a type");
        String w = t.text();
        switch (w) {
            case "sequence" -> {
                expect("<");
                Alias element = typeSpec(scope);
                int bound = 0;
                if (nextIs(",")) {
                    Token n = next("a sequence bound");
                    bound = MsgParser.number(digits(n), n.line());
                }
                expect(">");
                if (element.shape() != Field.Shape.SINGLE) {
                    throw new DefinitionException(t.line(), "sequences of arrays are not supported");
                }
                return element.shaped(bound > 0 ? Field.Shape.BOUNDED_SEQUENCE : Field.Shape.SEQUENCE, bound);
            }
            case "string", "wstring" -> {
                int bound = 0;
                if (nextIs("<")) {
                    Token n = next("a string bound");
                    bound = MsgParser.number(digits(n), n.line());
                    expect(">");
                }
                return new Alias(w.equals("string") ? Primitive.STRING : Primitive.WSTRING, null, t.line(),
                        Field.Shape.SINGLE, 0, bound);
            }
            case "unsigned" -> {
                Token n = next("short, long or long long");
                Primitive p = switch (n.text()) {
                    case "short" -> Primitive.UINT16;
                    case "long" -> nextIs("long") ? Primitive.UINT64 : Primitive.UINT32;
                    default -> throw new DefinitionException(n.line(), "'unsigned " + n.text() + "' is not a type");
                };
                return single(p);
            }
            case "long" -> {
                if (nextIs("double")) {
                    throw new DefinitionException(t.line(), "long double is not supported");
                }
                return single(nextIs("long") ? Primitive.INT64 : Primitive.INT32);
            }
            case "short" -> {
                return single(Primitive.INT16);
            }
            case "boolean" -> {
                return single(Primitive.BOOL);
            }
            case "octet" -> {
                return single(Primitive.BYTE);
            }
            case "float" -> {
                return single(Primitive.FLOAT32);
            }
            case "double" -> {
                return single(Primitive.FLOAT64);
            }
            case "wchar" -> throw new DefinitionException(t.line(), "wchar is not supported");
            default -> {
                Primitive p = Primitive.ofWord(w);
                if (p != null && p != Primitive.STRING && p != Primitive.WSTRING && p != Primitive.BOOL) {
                    return single(p);
                }
                checkIdentifier(t);
                String name = w.replace("::", "/");
                for (List<String> s = new ArrayList<>(scope); ; s.remove(s.size() - 1)) {
                    Alias a = typedefs.get(String.join("/", s) + (s.isEmpty() ? "" : "/") + name);
                    if (a != null) {
                        return a;
                    }
                    if (s.isEmpty()) {
                        break;
                    }
                }
                List<String> candidates = new ArrayList<>();
                for (List<String> s = new ArrayList<>(scope); ; s.remove(s.size() - 1)) {
                    candidates.add(String.join("/", s) + (s.isEmpty() ? "" : "/") + name);
                    if (s.isEmpty()) {
                        break;
                    }
                }
                return new Alias(null, List.copyOf(candidates), t.line(), Field.Shape.SINGLE, 0, 0);
            }
        }
    }

    private static Alias single(Primitive p) {
        return new Alias(p, null, 0, Field.Shape.SINGLE, 0, 0);
    }

    // ---- tokens

    private void skipAnnotations() throws DefinitionException {
        while (peekIs("@")) {
            at++;
            identifier();
            if (peekIs("(")) {
                int depth = 0;
                do {
                    Token t = next("the annotation's ')'");
                    if (!t.literal() && t.text().equals("(")) {
                        depth++;
                    } else if (!t.literal() && t.text().equals(")")) {
                        depth--;
                    }
                } while (depth > 0);
            }
        }
    }

    private String identifier() throws DefinitionException {
        Token t = next("a name");
        checkIdentifier(t);
        return t.text();
    }

    private static void checkIdentifier(Token t) throws DefinitionException {
        String s = t.text();
        if (t.literal() || s.isEmpty() || !(Character.isLetter(s.charAt(0)) || s.charAt(0) == '_')) {
            throw new DefinitionException(t.line(), "'" + MsgParser.cut(s) + "' where a name was expected");
        }
    }

    private static String digits(Token t) throws DefinitionException {
        if (t.literal() || t.text().isEmpty() || !t.text().chars().allMatch(Character::isDigit)) {
            throw new DefinitionException(t.line(), "'" + MsgParser.cut(t.text()) + "' where a number was expected");
        }
        return t.text();
    }

    private Token next(String what) throws DefinitionException {
        if (at >= tokens.size()) {
            throw new DefinitionException(lastLine(), "the schema ends where " + what + " was expected");
        }
        return tokens.get(at++);
    }

    private void expect(String s) throws DefinitionException {
        Token t = next("'" + s + "'");
        if (t.literal() || !t.text().equals(s)) {
            throw new DefinitionException(t.line(), "'" + MsgParser.cut(t.text()) + "' where '" + s + "' was expected");
        }
    }

    private boolean peekIs(String s) {
        return at < tokens.size() && !tokens.get(at).literal() && tokens.get(at).text().equals(s);
    }

    private boolean nextIs(String s) {
        if (peekIs(s)) {
            at++;
            return true;
        }
        return false;
    }

    private int lastLine() {
        return tokens.isEmpty() ? 1 : tokens.get(tokens.size() - 1).line();
    }

    private static List<Token> tokenize(String text) throws DefinitionException {
        List<Token> out = new ArrayList<>();
        int line = 1;
        int i = 0;
        int n = text.length();
        boolean lineStart = true;
        while (i < n) {
            char c = text.charAt(i);
            if (c == '\n') {
                line++;
                i++;
                lineStart = true;
                continue;
            }
            if (Character.isWhitespace(c)) {
                i++;
                continue;
            }
            if (lineStart && (c == '#' || c == '=' || text.startsWith("IDL:", i))) {
                // #include, a section's line of '=' and its 'IDL: pkg/msg/Type' name
                while (i < n && text.charAt(i) != '\n') {
                    i++;
                }
                continue;
            }
            lineStart = false;
            if (text.startsWith("//", i)) {
                while (i < n && text.charAt(i) != '\n') {
                    i++;
                }
            } else if (text.startsWith("/*", i)) {
                int end = text.indexOf("*/", i + 2);
                if (end < 0) {
                    throw new DefinitionException(line, "a comment '/*' is never closed");
                }
                for (int k = i; k < end; k++) {
                    if (text.charAt(k) == '\n') {
                        line++;
                    }
                }
                i = end + 2;
            } else if (c == '"') {
                int startLine = line;
                StringBuilder s = new StringBuilder();
                i++;
                while (true) {
                    if (i >= n) {
                        throw new DefinitionException(startLine, "a string literal is never closed");
                    }
                    char d = text.charAt(i++);
                    if (d == '"') {
                        break;
                    }
                    if (d == '\\' && i < n) {
                        d = text.charAt(i++);
                    }
                    if (d == '\n') {
                        line++;
                    }
                    s.append(d);
                }
                out.add(new Token(s.toString(), startLine, true));
            } else if (Character.isLetterOrDigit(c) || c == '_' || c == ':' || c == '.' || c == '-' || c == '+') {
                int start = i;
                while (i < n && (Character.isLetterOrDigit(text.charAt(i)) || text.charAt(i) == '_'
                        || text.charAt(i) == ':' || text.charAt(i) == '.'
                        || ((text.charAt(i) == '-' || text.charAt(i) == '+') && i == start))) {
                    i++;
                }
                out.add(new Token(text.substring(start, i), line, false));
            } else {
                out.add(new Token(String.valueOf(c), line, false));
                i++;
            }
        }
        return out;
    }
}
