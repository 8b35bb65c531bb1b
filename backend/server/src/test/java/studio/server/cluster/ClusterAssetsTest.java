package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import tools.jackson.databind.node.ObjectNode;

import studio.server.Await;
import studio.server.asset.Asset;
import studio.server.asset.AssetType;
import studio.server.asset.LocalAssets;
import studio.server.scene.gltf.TestGltf;
import studio.server.job.JobRequests;
import studio.server.job.JobState;
import studio.server.job.JobStatus;
import studio.server.scene.compiling.CompileRequest;
import studio.server.system.MemoryBudget;

/**
 * An asset uploaded to one member is rendered through another: the job's scene names it by id, the
 * accepting member reads it from the cluster's sealed map, and every member's workers render it.
 */
class ClusterAssetsTest {

    private static final String TETRAHEDRON = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

    private final List<TestMember> members = new ArrayList<>();
    private final String name = "test-" + UUID.randomUUID();

    @AfterEach
    void stopMembers() {
        members.forEach(TestMember::kill);
    }

    private static String scene(String mesh) {
        return """
                {"name": "asset-test", "image": {"width": 160, "height": 120, "format": "png"},
                 "camera": {"position": [2, 2, 3], "lookAt": [0.3, 0.3, 0.3]},
                 "render": {"samples": 4, "seed": 3},
                 "objects": [%s, {"type": "plane"}]}
                """.formatted(mesh);
    }

    private static String render(TestMember through, String json) throws Exception {
        byte[] bytes = json.getBytes(StandardCharsets.UTF_8);
        String id = through.jobs.submit(JobRequests.of(through.compiler.compile(CompileRequest.of(bytes)), bytes)).id();
        Await.until("job " + id + " to end", ClusterJobsTest.WAIT_MILLIS, () -> through.jobs.status(id).state().isFinal());
        JobStatus status = through.jobs.status(id);
        assertThat(status.state()).as(String.valueOf(status.error())).isEqualTo(JobState.DONE);
        return id;
    }

    @Test
    void aMeshAssetUploadedToOneMemberRendersThroughAnotherAsTheSameMeshInline() throws Exception {
        int[] ports = {TestMember.BASE_PORT, TestMember.BASE_PORT + 1};
        for (int port : ports) {
            TestMember member = new TestMember(name, port, ports);
            member.assets = new LocalAssets(1 << 20, MemoryBudget.unlimited(),
                    new ClusterAssets(member.data.assets())).meshes();
            members.add(member);
        }
        TestMember uploadedTo = members.get(0), renderedThrough = members.get(1);
        Await.until("the cluster to be safe", ClusterJobsTest.WAIT_MILLIS,
                () -> members.stream().allMatch(m -> m.hazelcast.getPartitionService().isClusterSafe()));
        Asset mesh = Asset.of(AssetType.OBJ, TETRAHEDRON.getBytes(StandardCharsets.UTF_8));
        new LocalAssets(1 << 20, MemoryBudget.unlimited(), new ClusterAssets(uploadedTo.data.assets())).put(mesh);

        String byAsset = render(renderedThrough, scene("{\"type\": \"mesh\", \"asset\": \"" + mesh.id() + "\"}"));
        String inline = render(renderedThrough, scene("{\"type\": \"mesh\", \"obj\": \"" + TETRAHEDRON.replace("\n", "\\n")
                + "\"}"));

        assertThat(renderedThrough.jobs.image(byAsset).bytes()).isEqualTo(renderedThrough.jobs.image(inline).bytes());
        assertThat(uploadedTo.jobs.image(byAsset).bytes()).isEqualTo(renderedThrough.jobs.image(inline).bytes());
    }

    @Test
    void aGltfWhoseBufferIsAnotherAssetRendersThroughAnotherMemberAsTheSameModelEmbedded() throws Exception {
        int[] ports = {TestMember.BASE_PORT, TestMember.BASE_PORT + 1};
        for (int port : ports) {
            TestMember member = new TestMember(name, port, ports);
            member.assets = new LocalAssets(1 << 20, MemoryBudget.unlimited(),
                    new ClusterAssets(member.data.assets())).meshes();
            members.add(member);
        }
        TestMember uploadedTo = members.get(0), renderedThrough = members.get(1);
        Await.until("the cluster to be safe", ClusterJobsTest.WAIT_MILLIS,
                () -> members.stream().allMatch(m -> m.hazelcast.getPartitionService().isClusterSafe()));
        LocalAssets upload = new LocalAssets(1 << 20, MemoryBudget.unlimited(), new ClusterAssets(uploadedTo.data.assets()));
        Asset buffer = Asset.of(AssetType.BIN, TestGltf.triangleBuffer());
        upload.put(buffer);
        ObjectNode embedded = TestGltf.triangle("[{\"scale\": [2, 2, 2], \"mesh\": 0}]");
        ObjectNode byId = embedded.deepCopy();
        ((ObjectNode) byId.get("buffers").get(0)).put("uri", buffer.id());
        Asset model = Asset.of(AssetType.GLTF, TestGltf.bytes(byId));
        upload.put(model);
        Asset whole = Asset.of(AssetType.GLTF, TestGltf.bytes(embedded));
        upload.put(whole);

        String viaIds = render(renderedThrough, scene("{\"type\": \"gltf\", \"asset\": \"" + model.id() + "\"}"));
        String inOne = render(renderedThrough, scene("{\"type\": \"gltf\", \"asset\": \"" + whole.id() + "\"}"));
        String nothing = render(renderedThrough, scene("{\"type\": \"sphere\", \"radius\": 0.01}"));

        assertThat(renderedThrough.jobs.image(viaIds).bytes()).isEqualTo(renderedThrough.jobs.image(inOne).bytes());
        assertThat(renderedThrough.jobs.image(viaIds).bytes()).isNotEqualTo(renderedThrough.jobs.image(nothing).bytes());
    }

    @Test
    void bytesThatDoNotHashToTheirIdAreNotTakenFromTheCluster() throws Exception {
        int[] ports = {TestMember.BASE_PORT};
        TestMember member = new TestMember(name, ports[0], ports);
        members.add(member);
        ClusterAssets shared = new ClusterAssets(member.data.assets());
        Asset real = Asset.of(AssetType.OBJ, TETRAHEDRON.getBytes(StandardCharsets.UTF_8));
        Asset forged = new Asset(real.id(), AssetType.OBJ, "v 9 9 9\n".getBytes(StandardCharsets.UTF_8));
        shared.share(forged); // a member that writes other bytes under an id (it holds the secret)

        LocalAssets store = new LocalAssets(1 << 20, MemoryBudget.unlimited(), shared);
        assertThat(store.get(real.id())).isNull();
        assertThat(store.meshes().obj(real.id())).isNull();
    }
}
