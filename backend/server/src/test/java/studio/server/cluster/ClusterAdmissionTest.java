package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.Serializable;
import java.util.Date;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import com.hazelcast.client.HazelcastClient;
import com.hazelcast.client.config.ClientConfig;
import com.hazelcast.core.Hazelcast;
import com.hazelcast.core.HazelcastInstance;
import com.hazelcast.nio.serialization.HazelcastSerializationException;

import io.micrometer.core.instrument.simple.SimpleMeterRegistry;

/**
 * Who the cluster admits: members with its secret, and nothing else. A Hazelcast client does not get
 * in (even with the cluster's name), a member of another secret forms a cluster of its own, and a
 * value written by Java serialization is refused whatever its class.
 */
class ClusterAdmissionTest {

    private static final String OTHER_SECRET = "another cluster's secret, 32 bytes or more";
    /** The first of the ports this JVM's test members use. */
    private static final int P = TestMember.BASE_PORT;
    private final String name = "admission-" + UUID.randomUUID();
    private final java.util.ArrayList<HazelcastInstance> members = new java.util.ArrayList<>();

    @AfterEach
    void stop() {
        members.forEach(member -> member.getLifecycleService().terminate());
    }

    private HazelcastInstance member(String secret, int port, int... ports) {
        ClusterProperties properties = TestMember.properties(name, port, ports);
        properties = new ClusterProperties(port, properties.members(), name, "127.0.0.1", secret);
        HazelcastInstance member = Hazelcast.newHazelcastInstance(MemberConfig.of(properties));
        members.add(member);
        return member;
    }

    @Test
    void aHazelcastClientCannotConnectEvenWithTheClustersName() {
        HazelcastInstance member = member(TestMember.SECRET, P, P);
        ClientConfig client = new ClientConfig();
        client.setClusterName(member.getConfig().getClusterName());
        client.getNetworkConfig().setAddresses(List.of("127.0.0.1:" + P));
        client.getConnectionStrategyConfig().getConnectionRetryConfig().setClusterConnectTimeoutMillis(3_000);
        client.setProperty("hazelcast.logging.type", "slf4j");

        assertThatThrownBy(() -> HazelcastClient.newHazelcastClient(client).shutdown())
                .isInstanceOf(IllegalStateException.class);
        assertThat(member.getClientService().getConnectedClients()).isEmpty();
    }

    @Test
    void aMemberWithAnotherSecretDoesNotJoin() throws Exception {
        HazelcastInstance member = member(TestMember.SECRET, P, P, P + 1);
        HazelcastInstance stranger = member(OTHER_SECRET, P + 1, P, P + 1);
        Thread.sleep(3_000);
        assertThat(member.getCluster().getMembers()).hasSize(1);
        assertThat(stranger.getCluster().getMembers()).hasSize(1);
        HazelcastInstance friend = member(TestMember.SECRET, P + 2, P);
        assertThat(friend.getCluster().getMembers()).hasSize(2);
    }

    /** A class of an outsider's, as a member would have to load it to read it. */
    record Outsider(String payload) implements Serializable {
    }

    @Test
    void aJavaSerializedValueIsRefusedWhateverItsClass() {
        HazelcastInstance member = member(TestMember.SECRET, P, P, P + 1);
        HazelcastInstance other = member(TestMember.SECRET, P + 1, P, P + 1);
        assertThat(member.getCluster().getMembers()).hasSize(2);

        for (int i = 0; i < 8; i++) { // keys on both members' partitions
            String date = "date-" + i, outsider = "outsider-" + i;
            // a Date inside a value Hazelcast has no serializer of its own for: written by Java serialization
            other.getMap(ClusterMaps.JOBS).set(date, new AtomicReference<>(new Date(0)));
            other.getMap(ClusterMaps.JOBS).set(outsider, new Outsider("x"));
            assertThatThrownBy(() -> member.getMap(ClusterMaps.JOBS).get(date))
                    .isInstanceOf(HazelcastSerializationException.class)
                    .rootCause().isInstanceOf(SecurityException.class)
                    .hasMessageContaining("java.util.concurrent.atomic.AtomicReference");
            assertThatThrownBy(() -> member.getMap(ClusterMaps.JOBS).get(outsider))
                    .isInstanceOf(HazelcastSerializationException.class)
                    .rootCause().isInstanceOf(SecurityException.class).hasMessageContaining(Outsider.class.getName());
        }
    }

    @Test
    void aValueThatIsNotSealedBytesReadsAsAbsentAndIsCounted() {
        HazelcastInstance member = member(TestMember.SECRET, P, P);
        SimpleMeterRegistry registry = new SimpleMeterRegistry();
        ClusterData data = new ClusterData(member, new Seal(ClusterSecret.of(TestMember.properties(name, P, P)),
                registry));
        member.getMap(ClusterMaps.JOBS).set("date", new Date(0));
        member.getMap(ClusterMaps.JOBS).set("outsider", new Outsider("x"));

        assertThat(data.jobs().get("date")).isNull();
        assertThat(data.jobs().get("outsider")).isNull();
        assertThat(data.jobs().entries()).isEmpty();
        assertThat(registry.get("studio.cluster.rejected").tag("structure", ClusterMaps.JOBS).counter().count())
                .isGreaterThanOrEqualTo(4);
    }
}
