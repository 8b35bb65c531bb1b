package studio.server.preview;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

import studio.server.preview.patch.PatchOperation;
import studio.server.scene.format.InvalidSceneException;

/** A live-view message with a patch: read with its base, and each of its bad forms named. */
class PreviewRequestPatchTest {

    private static PreviewRequest parse(String message) {
        return PreviewRequest.parse(message.replace('\'', '"').getBytes(StandardCharsets.UTF_8), 2048, 2048);
    }

    private static void refused(String message, String field) {
        assertThatThrownBy(() -> parse(message)).isInstanceOfSatisfying(InvalidSceneException.class,
                e -> assertThat(e.problems()).anySatisfy(p -> assertThat(p.field()).isEqualTo(field)));
    }

    @Test
    void readsAPatchWithItsBase() {
        PreviewRequest request = parse("{'revision': 4, 'base': 3, 'width': 64, 'height': 48,"
                + " 'patch': [{'op': 'replace', 'path': '/objects/0/center', 'value': [0.1, 1e-7, 2.50]}]}");
        assertThat(request.base()).isEqualTo(3);
        assertThat(request.scene()).isNull();
        assertThat(request.patch().operations()).singleElement().satisfies(op -> {
            assertThat(op.op()).isEqualTo(PatchOperation.Op.REPLACE);
            assertThat(op.path()).containsExactly("objects", "0", "center");
            assertThat(op.value().toString()).as("numbers as written").isEqualTo("[0.1,1E-7,2.50]");
        });
        assertThat(parse("{'revision': 1, 'scene': {'objects': [{'type': 'plane'}]}}").base()).isEqualTo(-1);
    }

    @Test
    void refusesEachBadForm() {
        refused("{'revision': 4, 'patch': []}", "base");
        refused("{'revision': 4, 'base': 3, 'scene': {'objects': []}}", "base");
        refused("{'revision': 4, 'base': -1, 'patch': []}", "base");
        refused("{'revision': 4, 'base': 'three', 'patch': []}", "base");
        refused("{'revision': 4, 'base': 3, 'patch': [], 'scene': {'objects': []}}", "patch");
        refused("{'revision': 4, 'base': 3, 'patch': {'op': 'add'}}", "patch");
        refused("{'revision': 4, 'base': 3, 'patch': [{'op': 'add', 'op': 'remove', 'path': '/a', 'value': 1}]}", "patch");
        refused("{'revision': 4, 'base': 3, 'patch': [{'op': 'add', 'path': '/a'}]}", "patch[0].value");
        refused("{'revision': 4, 'base': 3, 'patch': [{'op': 'add', 'path': '/a/~x', 'value': 1}]}", "patch[0].path");
        refused("{'revision': 4}", "scene");
    }

    @Test
    void tellsAWholeSceneFromAPatchByTheFirstOfTheirMembers() {
        assertThat(PreviewRequest.isWholeScene("{'revision': 1, 'scene': {}}".replace('\'', '"').getBytes(StandardCharsets.UTF_8))).isTrue();
        assertThat(PreviewRequest.isWholeScene("{'revision': 2, 'width': [1, {'scene': 1}], 'base': 1, 'patch': [], 'scene': {}}"
                .replace('\'', '"').getBytes(StandardCharsets.UTF_8))).isFalse();
        assertThat(PreviewRequest.isWholeScene("[1]".getBytes(StandardCharsets.UTF_8))).isFalse();
        assertThat(PreviewRequest.isWholeScene("{\"revision\": ".getBytes(StandardCharsets.UTF_8))).isFalse();
    }
}
