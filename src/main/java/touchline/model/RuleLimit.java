package touchline.model;

/**
 * One figure of a league's rules as a profile states it: a number, no limit at all, or a
 * figure the rulebook has but Touchline does not know (then it is shown as "not known", never
 * guessed).
 *
 * @param kind  which of the three
 * @param value the number when {@code kind} is {@link Kind#VALUE}, else 0
 */
public record RuleLimit(Kind kind, long value) {

    public enum Kind { VALUE, NONE, UNKNOWN }

    public static final RuleLimit NONE = new RuleLimit(Kind.NONE, 0);
    public static final RuleLimit UNKNOWN = new RuleLimit(Kind.UNKNOWN, 0);

    public static RuleLimit of(long value) {
        return new RuleLimit(Kind.VALUE, value);
    }

    public boolean known() {
        return kind == Kind.VALUE;
    }

    /** "12000", "no limit" or "not known in this profile". */
    public String describe() {
        return switch (kind) {
            case VALUE -> Long.toString(value);
            case NONE -> "no limit";
            case UNKNOWN -> "not known in this profile";
        };
    }
}
