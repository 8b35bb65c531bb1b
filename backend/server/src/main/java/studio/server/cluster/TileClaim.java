package studio.server.cluster;

import java.io.Serializable;

/** A tile a worker has taken: which member took it and at which attempt. */
record TileClaim(String member, int attempt) implements Serializable {
}
