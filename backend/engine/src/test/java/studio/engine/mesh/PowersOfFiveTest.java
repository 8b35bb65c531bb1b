package studio.engine.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.math.BigInteger;

import org.junit.jupiter.api.Test;

/** The written-out powers of five are the ones BigInteger works out, entry by entry. */
class PowersOfFiveTest {

    @Test
    void everyEntryIsFiveToTheQNormalisedAndTruncatedOrItsReciprocalRoundedUp() {
        BigInteger mask64 = BigInteger.ONE.shiftLeft(64).subtract(BigInteger.ONE);
        assertEquals(2 * (PowersOfFive.MAX_Q - PowersOfFive.MIN_Q + 1), PowersOfFive.TABLE.length);
        for (int q = PowersOfFive.MIN_Q; q <= PowersOfFive.MAX_Q; q++) {
            BigInteger c;
            if (q < 0) {
                BigInteger power5 = BigInteger.valueOf(5).pow(-q);
                int z = power5.subtract(BigInteger.ONE).bitLength(); // least z with 2^z >= 5^-q
                int b = q >= -27 ? z + 127 : 2 * z + 128;
                c = BigInteger.ONE.shiftLeft(b).divide(power5).add(BigInteger.ONE);
                while (c.bitLength() > 128) {
                    c = c.shiftRight(1);
                }
            } else {
                c = BigInteger.valueOf(5).pow(q);
                int bits = c.bitLength();
                c = bits < 128 ? c.shiftLeft(128 - bits) : c.shiftRight(bits - 128);
            }
            int i = 2 * (q - PowersOfFive.MIN_Q);
            assertEquals(c.shiftRight(64).longValue(), PowersOfFive.TABLE[i], "high bits, q = " + q);
            assertEquals(c.and(mask64).longValue(), PowersOfFive.TABLE[i + 1], "low bits, q = " + q);
        }
    }
}
