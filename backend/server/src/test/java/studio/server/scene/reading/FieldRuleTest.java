package studio.server.scene.reading;

import static org.assertj.core.api.Assertions.assertThat;

import java.math.BigDecimal;
import java.util.List;
import java.util.function.Predicate;

import org.junit.jupiter.api.Test;

/**
 * The decimal rules compare a double with their bound exactly, as the full path's validator does,
 * without expanding every double into a BigDecimal: checked where comparing with the double nearest
 * the bound would go wrong, on the doubles next to bounds that no double equals.
 */
class FieldRuleTest {

    /** Doubles around each bound: the one nearest it, its neighbours, and the extremes. */
    private static List<Double> around(double nearest) {
        return List.of(nearest, Math.nextDown(nearest), Math.nextUp(nearest), 0.0, Double.MIN_VALUE, -Double.MIN_VALUE,
                Double.MAX_VALUE, -Double.MAX_VALUE, 1.0, -1.0);
    }

    @Test
    void aDoubleNextToABoundNoDoubleEqualsIsOnItsExactSide() {
        // 0.3's nearest double lies below 0.3 and 0.1's above 0.1: comparing with them alone misjudges one each
        assertThat(new DecimalRule("0.3", true, true).check().test(0.3)).isFalse();
        assertThat(new DecimalRule("0.1", true, false).check().test(0.1)).isFalse();
        assertThat(new DecimalRule("0.3", true, true).check().test(Math.nextUp(0.3))).isTrue();
        // 2^53 + 1 and 0.999... round to doubles (2^53, 1) that they are not
        for (String bound : List.of("0.1", "0.3", "-0.7", "1e-400", "-1e-400", "1e400", "0", "1", "180", "1e12",
                "9007199254740993", "9007199254740992", "-9007199254740993", "0.99999999999999999999")) {
            BigDecimal exact = new BigDecimal(bound);
            for (boolean inclusive : List.of(true, false)) {
                for (boolean min : List.of(true, false)) {
                    Predicate<Object> check = new DecimalRule(bound, inclusive, min).check();
                    for (double d : around(exact.doubleValue())) {
                        // an infinity (1e400's nearest) and -0.0 are left to the full path (FieldRule.finite)
                        boolean judged = Double.isFinite(d) && Double.compare(d, -0.0) != 0;
                        int sign = judged ? new BigDecimal(d).compareTo(exact) : 0;
                        boolean expected = judged && passes(sign, min, inclusive);
                        assertThat(check.test(d)).as("%s %s %s %s", d, min ? ">" : "<", inclusive ? "=" : "", bound)
                                .isEqualTo(expected);
                    }
                    for (long whole : List.of(3L, 1L, 9007199254740991L, 9007199254740992L, 9007199254740993L,
                            -9007199254740993L, Long.MAX_VALUE, Long.MIN_VALUE)) {
                        boolean expected = passes(BigDecimal.valueOf(whole).compareTo(exact), min, inclusive);
                        assertThat(check.test(whole)).as("%d %s %s %s", whole, min ? ">" : "<", inclusive ? "=" : "", bound)
                                .isEqualTo(expected);
                    }
                }
            }
        }
    }

    /** Whether a value whose exact difference from the bound has this sign passes the rule. */
    private static boolean passes(int sign, boolean min, boolean inclusive) {
        return min ? (inclusive ? sign >= 0 : sign > 0) : (inclusive ? sign <= 0 : sign < 0);
    }

    /** DecimalMin or DecimalMax, as one value for the loops above. */
    private record DecimalRule(String bound, boolean inclusive, boolean min) {
        Predicate<Object> check() {
            return min ? new FieldRule.DecimalMin(bound, inclusive).check() : new FieldRule.DecimalMax(bound, inclusive).check();
        }
    }
}
