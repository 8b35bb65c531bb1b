package studio.server.cluster;

import java.nio.charset.StandardCharsets;
import java.util.HexFormat;

/**
 * The secret every member of a cluster holds (studio.cluster.secret): from it, by HKDF, the tag in
 * the cluster's name (a member with another secret never joins) and one sealing key per purpose
 * ({@link Seal}). Without a secret a clustered member refuses to start, unless
 * studio.cluster.insecure=true, which uses a fixed, public demo secret (the same code path).
 */
final class ClusterSecret {

    /** The least a secret may be: 32 bytes (e.g. {@code openssl rand -base64 48}). */
    static final int MIN_BYTES = 32;
    /** The secret of an insecure demo cluster: public, so it protects nothing. */
    static final String DEMO = "ray-studio insecure demo secret, protects nothing";
    private static final byte[] SALT = "ray-studio cluster v1".getBytes(StandardCharsets.UTF_8);

    private final byte[] prk;
    private final boolean insecure;

    private ClusterSecret(byte[] secret, boolean insecure) {
        this.prk = Hkdf.extract(SALT, secret);
        this.insecure = insecure;
    }

    /**
     * The secret of a clustered member's configuration.
     *
     * @throws Refused with a one-line reason if there is none (and insecure is not set), or it is too short
     */
    static ClusterSecret of(ClusterProperties cluster) {
        byte[] secret = cluster.secret().getBytes(StandardCharsets.UTF_8);
        if (secret.length == 0) {
            if (!cluster.insecure()) {
                throw new Refused("a clustered member needs studio.cluster.secret (STUDIO_CLUSTER_SECRET, "
                        + "at least " + MIN_BYTES + " bytes, e.g. openssl rand -base64 48), or studio.cluster.insecure=true "
                        + "for a demo");
            }
            return new ClusterSecret(DEMO.getBytes(StandardCharsets.UTF_8), true);
        }
        if (secret.length < MIN_BYTES) {
            throw new Refused("studio.cluster.secret is " + secret.length + " bytes; it must be at least "
                    + MIN_BYTES + " (e.g. openssl rand -base64 48)");
        }
        return new ClusterSecret(secret, false);
    }

    boolean insecure() {
        return insecure;
    }

    /** A 256-bit key for one purpose (a structure's family), independent of every other purpose's. */
    byte[] key(String purpose) {
        return Hkdf.expand(prk, ("seal " + purpose).getBytes(StandardCharsets.UTF_8), 32);
    }

    /**
     * The cluster's name as Hazelcast sees it: the configured name and a tag of the secret, so that
     * members of different secrets form different clusters. The tag travels in the clear on the
     * member network: it identifies the secret without revealing it.
     */
    String clusterName(String name) {
        byte[] tag = Hkdf.expand(prk, "cluster name".getBytes(StandardCharsets.UTF_8), 12);
        return name + "-" + HexFormat.of().formatHex(tag);
    }

    /** A clustered member's configuration without a usable secret: the member does not start. */
    static final class Refused extends IllegalStateException {

        Refused(String reason) {
            super(reason);
        }
    }
}
