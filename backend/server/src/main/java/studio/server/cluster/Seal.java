package studio.server.cluster;

import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.security.SecureRandom;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import javax.crypto.AEADBadTagException;
import javax.crypto.Cipher;
import javax.crypto.SecretKey;
import javax.crypto.spec.GCMParameterSpec;
import javax.crypto.spec.SecretKeySpec;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import io.micrometer.core.instrument.Counter;
import io.micrometer.core.instrument.MeterRegistry;

/**
 * Seals what a member puts into the cluster, and opens what it reads: AES-256-GCM with a key per
 * family of structures (derived from the {@link ClusterSecret}), a random 96-bit nonce per value, and
 * the structure's name and the entry's key as associated data, so that a value opens only where it
 * was put. A value that does not open (forged, replayed under another key, or from a member of
 * another secret) is dropped: counted in {@code studio.cluster.rejected{structure=...}} and logged at
 * most once per {@value #LOG_EVERY_SECONDS} s per family.
 *
 * <p>Layout: version (1 byte) | nonce (12) | ciphertext | tag (16).
 */
final class Seal {

    private static final Logger log = LoggerFactory.getLogger(Seal.class);
    static final long LOG_EVERY_SECONDS = 10;
    private static final byte VERSION = 1;
    private static final int NONCE = 12, TAG_BITS = 128, OVERHEAD = 1 + NONCE + TAG_BITS / 8;
    private static final String AES_GCM = "AES/GCM/NoPadding";
    /** The family, and structure, of the values {@link #warmUp} seals: no value in the cluster has it. */
    static final String WARM_UP = "studio-seal-warm-up";

    private final ClusterSecret secret;
    private final MeterRegistry registry;
    private final SecureRandom random = new SecureRandom();
    /**
     * Each thread's cipher, initialized again for every value: a {@code Cipher.getInstance} per value
     * looked the provider up every time, and the JIT was still compiling that lookup in two members'
     * warm jobs (docs/cluster.md, "Where two members' CPU goes").
     */
    private final ThreadLocal<Cipher> ciphers = ThreadLocal.withInitial(Seal::newCipher);
    private final Map<String, SecretKey> keys = new ConcurrentHashMap<>();
    private final Map<String, Counter> rejected = new ConcurrentHashMap<>();
    private final Map<String, AtomicLong> lastLogged = new ConcurrentHashMap<>();

    Seal(ClusterSecret secret, MeterRegistry registry) {
        this.secret = secret;
        this.registry = registry;
    }

    /** Seals {@code plain} for the entry {@code key} of the structure {@code name} of the family {@code family}. */
    byte[] seal(String family, String name, Object key, byte[] plain) {
        byte[] out = new byte[OVERHEAD + plain.length];
        out[0] = VERSION;
        byte[] nonce = new byte[NONCE];
        random.nextBytes(nonce);
        System.arraycopy(nonce, 0, out, 1, NONCE);
        try {
            Cipher cipher = ciphers.get();
            cipher.init(Cipher.ENCRYPT_MODE, key(family), new GCMParameterSpec(TAG_BITS, nonce));
            cipher.updateAAD(aad(name, key));
            cipher.doFinal(plain, 0, plain.length, out, 1 + NONCE);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("could not seal a value of " + name, e);
        }
        return out;
    }

    /** The plain bytes of a sealed value, or null (rejected, counted, logged) if it does not open; null for null. */
    byte[] open(String family, String name, Object key, byte[] sealed) {
        if (sealed == null) {
            return null;
        }
        if (sealed.length < OVERHEAD || sealed[0] != VERSION) {
            reject(family, name, "not a sealed value");
            return null;
        }
        try {
            Cipher cipher = ciphers.get();
            cipher.init(Cipher.DECRYPT_MODE, key(family), new GCMParameterSpec(TAG_BITS, sealed, 1, NONCE));
            cipher.updateAAD(aad(name, key));
            return cipher.doFinal(sealed, 1 + NONCE, sealed.length - 1 - NONCE);
        } catch (AEADBadTagException e) {
            reject(family, name, "its seal does not verify");
            return null;
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("could not open a value of " + name, e);
        }
    }

    /**
     * Seals and opens {@code values} values of {@code bytes} bytes each (under a key of their own
     * family, read by no one), so that the JIT compiles AES-GCM's intrinsics before the first job:
     * a fresh JVM on one core spent 2.9 ms, then 1.3 ms, per tile result sealed and opened in its
     * first two 180-tile rounds, 0.07 ms after ({@code docs/cluster.md}, "What the seal costs").
     */
    void warmUp(int values, int bytes) {
        byte[] plain = new byte[bytes];
        for (int i = 0; i < values; i++) {
            open(WARM_UP, WARM_UP, i, seal(WARM_UP, WARM_UP, i, plain));
        }
    }

    /** Drops a value that opened but makes no sense (a tile result of the wrong size, say): counted and logged as a bad seal. */
    void reject(String family, String name, String why) {
        rejected.computeIfAbsent(family, f -> Counter.builder("studio.cluster.rejected")
                .description("Values read from the cluster and dropped: not sealed with this cluster's secret, or invalid")
                .tag("structure", f).register(registry)).increment();
        AtomicLong last = lastLogged.computeIfAbsent(family, f -> new AtomicLong(Long.MIN_VALUE));
        long now = System.nanoTime(), then = last.get();
        if ((then == Long.MIN_VALUE || now - then > TimeUnit.SECONDS.toNanos(LOG_EVERY_SECONDS))
                && last.compareAndSet(then, now)) {
            log.warn("dropped a value read from {} ({}); such values are counted in studio.cluster.rejected, "
                    + "logged at most every {} s", name, why, LOG_EVERY_SECONDS);
        }
    }

    private static Cipher newCipher() {
        try {
            return Cipher.getInstance(AES_GCM);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("no " + AES_GCM + " in this JVM", e);
        }
    }

    private SecretKey key(String family) {
        return keys.computeIfAbsent(family, f -> new SecretKeySpec(secret.key(f), "AES"));
    }

    private static byte[] aad(String name, Object key) {
        return (name + '\u0000' + key).getBytes(StandardCharsets.UTF_8);
    }
}
