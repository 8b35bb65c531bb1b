package studio.server.cluster;

import org.springframework.boot.diagnostics.AbstractFailureAnalyzer;
import org.springframework.boot.diagnostics.FailureAnalysis;

/** A clustered member without a usable secret does not start: the reason in one line, not a stack trace. */
final class ClusterSecretFailureAnalyzer extends AbstractFailureAnalyzer<ClusterSecret.Refused> {

    @Override
    protected FailureAnalysis analyze(Throwable rootFailure, ClusterSecret.Refused cause) {
        return new FailureAnalysis(cause.getMessage(), "Give every member the same secret in STUDIO_CLUSTER_SECRET "
                + "(on Kubernetes, from the Secret ray-studio-cluster), or start without studio.cluster.members "
                + "for a service of one.", cause);
    }
}
