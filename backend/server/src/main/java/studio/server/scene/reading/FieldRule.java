package studio.server.scene.reading;

import java.lang.annotation.Annotation;
import java.math.BigDecimal;
import java.util.List;
import java.util.function.Predicate;

import jakarta.validation.Constraint;

/**
 * One Bean Validation constraint of a scene record's field, as the fast path checks it
 * ({@link FastPathBinder}). The rules are plain data, listed per field in {@link SceneConstraints},
 * which a test generates from the records' annotations ({@link #of}). Reading the annotations
 * themselves at run time made the JDK spin a proxy class for each of 19 annotation types, most of
 * the binder's set-up in a cold command-line render (with the table, a still life at one
 * sample takes 0.94 of the time).
 *
 * <p>Every rule passes null but {@link NotNull}; the full path's validator agrees.
 */
sealed interface FieldRule {

    /** The rule as a test of a bound value, made once when the binder is built. */
    Predicate<Object> check();

    record NotNull() implements FieldRule {
        @Override
        public Predicate<Object> check() {
            return value -> value != null;
        }
    }

    record Finite() implements FieldRule {
        @Override
        public Predicate<Object> check() {
            return value -> value == null || Double.isFinite((Double) value);
        }
    }

    record Positive() implements FieldRule {
        @Override
        public Predicate<Object> check() {
            return value -> value == null || signum(value) > 0;
        }
    }

    record PositiveOrZero() implements FieldRule {
        @Override
        public Predicate<Object> check() {
            return value -> value == null || signum(value) >= 0;
        }
    }

    record Min(long value) implements FieldRule {
        @Override
        public Predicate<Object> check() {
            return v -> v == null || ((Number) v).longValue() >= value;
        }
    }

    record Max(long value) implements FieldRule {
        @Override
        public Predicate<Object> check() {
            return v -> v == null || ((Number) v).longValue() <= value;
        }
    }

    record DecimalMin(String value, boolean inclusive) implements FieldRule {
        @Override
        public Predicate<Object> check() {
            BigDecimal bound = new BigDecimal(value);
            double nearest = bound.doubleValue();
            return v -> v == null || finite(v)
                    && (inclusive ? compare(v, bound, nearest) >= 0 : compare(v, bound, nearest) > 0);
        }
    }

    record DecimalMax(String value, boolean inclusive) implements FieldRule {
        @Override
        public Predicate<Object> check() {
            BigDecimal bound = new BigDecimal(value);
            double nearest = bound.doubleValue();
            return v -> v == null || finite(v)
                    && (inclusive ? compare(v, bound, nearest) <= 0 : compare(v, bound, nearest) < 0);
        }
    }

    /** A regular expression without flags, matched against the whole text. */
    record Pattern(String regexp) implements FieldRule {
        @Override
        public Predicate<Object> check() {
            java.util.regex.Pattern regex = java.util.regex.Pattern.compile(regexp);
            return value -> value == null || regex.matcher((String) value).matches();
        }
    }

    /** A text of min to max code points, not normalised. */
    record CodePointLength(int min, int max) implements FieldRule {
        @Override
        public Predicate<Object> check() {
            return value -> {
                if (value == null) {
                    return true;
                }
                int count = ((String) value).codePointCount(0, ((String) value).length());
                return count >= min && count <= max;
            };
        }
    }

    /** Three numbers ({@link studio.server.scene.format.Vector}). */
    record Vector() implements FieldRule {
        @Override
        public Predicate<Object> check() {
            return value -> value == null || ((List<?>) value).size() == 3;
        }
    }

    /** Two numbers ({@link studio.server.scene.format.Pair}). */
    record Pair() implements FieldRule {
        @Override
        public Predicate<Object> check() {
            return value -> value == null || ((List<?>) value).size() == 2;
        }
    }

    /** Not every number zero ({@link studio.server.scene.format.NonZeroVector}). */
    record NonZeroVector() implements FieldRule {
        @Override
        public Predicate<Object> check() {
            return value -> {
                if (value == null) {
                    return true;
                }
                for (Object component : (List<?>) value) {
                    if (!(component instanceof Double d) || d != 0) {
                        return true;
                    }
                }
                return false;
            };
        }
    }

    /**
     * The rule an annotation states, null for an annotation that is no constraint (such as
     * {@code @Valid}). A constraint this class does not know, or a form of one it does not check
     * (regex flags, a normalised length), throws: a new rule can never be skipped silently.
     */
    static FieldRule of(Annotation annotation, String where) {
        if (annotation instanceof jakarta.validation.constraints.NotNull) {
            return new NotNull();
        }
        if (annotation instanceof studio.server.scene.format.Finite) {
            return new Finite();
        }
        if (annotation instanceof jakarta.validation.constraints.Positive) {
            return new Positive();
        }
        if (annotation instanceof jakarta.validation.constraints.PositiveOrZero) {
            return new PositiveOrZero();
        }
        if (annotation instanceof jakarta.validation.constraints.Min min) {
            return new Min(min.value());
        }
        if (annotation instanceof jakarta.validation.constraints.Max max) {
            return new Max(max.value());
        }
        if (annotation instanceof jakarta.validation.constraints.DecimalMin min) {
            return new DecimalMin(min.value(), min.inclusive());
        }
        if (annotation instanceof jakarta.validation.constraints.DecimalMax max) {
            return new DecimalMax(max.value(), max.inclusive());
        }
        if (annotation instanceof jakarta.validation.constraints.Pattern pattern && pattern.flags().length == 0) {
            return new Pattern(pattern.regexp());
        }
        if (annotation instanceof org.hibernate.validator.constraints.CodePointLength length
                && length.normalizationStrategy()
                        == org.hibernate.validator.constraints.CodePointLength.NormalizationStrategy.NONE) {
            return new CodePointLength(length.min(), length.max());
        }
        if (annotation instanceof studio.server.scene.format.Vector) {
            return new Vector();
        }
        if (annotation instanceof studio.server.scene.format.Pair) {
            return new Pair();
        }
        if (annotation instanceof studio.server.scene.format.NonZeroVector) {
            return new NonZeroVector();
        }
        if (annotation.annotationType().isAnnotationPresent(Constraint.class)) {
            throw new IllegalStateException("the fast path does not check " + annotation + " at " + where);
        }
        return null;
    }

    /** Finite and not -0.0 (left to the full path, whose decimal rules compare it in their own way). */
    private static boolean finite(Object value) {
        return !(value instanceof Double d) || Double.isFinite(d) && Double.compare(d, -0.0) != 0;
    }

    private static int signum(Object value) {
        if (value instanceof Double d) {
            // as Hibernate Validator: -0.0 is negative (refused by @PositiveOrZero); NaN here -1, refused
            return d > 0 ? 1 : Double.compare(d, 0.0) == 0 ? 0 : -1;
        }
        return Long.signum(((Number) value).longValue());
    }

    /**
     * The sign of {@code value} minus {@code bound}, exactly, as the full path's decimal rules compare.
     * A double other than {@code nearest} (the double nearest the bound) lies on the bound's side
     * that it lies of {@code nearest}: the bound is {@code nearest} or lies between it and its
     * neighbour, and no double lies between those two. Only a value equal to {@code nearest} is
     * expanded into a BigDecimal, which for every checked number cost a large scene's reading much
     * of its time (docs/speed.md, "Start-up").
     */
    private static int compare(Object value, BigDecimal bound, double nearest) {
        if (value instanceof Double d) {
            return d != nearest ? Double.compare(d, nearest) : new BigDecimal(d).compareTo(bound);
        }
        return BigDecimal.valueOf(((Number) value).longValue()).compareTo(bound);
    }
}
