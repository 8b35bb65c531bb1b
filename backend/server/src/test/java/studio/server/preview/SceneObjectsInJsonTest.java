package studio.server.preview;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

import studio.server.scene.format.InvalidSceneException;

/** The live view's message reader finds each object of its scene by the object's bytes, in the pass that reads the message. */
class SceneObjectsInJsonTest {

    /** The ranges of a live-view message with {@code scene}, counted from the scene's first byte. */
    private static int[] ranges(String scene) {
        byte[] message = ("{\"revision\": 1, \"scene\": " + scene + "}").getBytes(StandardCharsets.UTF_8);
        return PreviewRequest.parse(message, 2048, 2048).objects();
    }

    @Test
    void eachElementOfTheTopLevelObjectsArrayByItsBytes() {
        String scene = "{\"camera\": {\"objects\": [1]}, \"objects\": [ {\"type\": \"sphere\", \"name\": \"é}\"},"
                + "{\"type\": \"box\", \"size\": [1, 2, 3]} ], \"lights\": []}";
        byte[] bytes = scene.getBytes(StandardCharsets.UTF_8);

        int[] ranges = ranges(scene);

        assertThat(ranges).hasSize(8);
        assertThat(new String(bytes, ranges[0], ranges[1] - ranges[0], StandardCharsets.UTF_8))
                .isEqualTo("{\"type\": \"sphere\", \"name\": \"é}\"}");
        assertThat(new String(bytes, ranges[4], ranges[5] - ranges[4], StandardCharsets.UTF_8))
                .isEqualTo("{\"type\": \"box\", \"size\": [1, 2, 3]}");
        assertThat(ranges[2]).isEqualTo(-1);
        assertThat(ranges[7]).isEqualTo(-1);
    }

    @Test
    void anInlineMeshsTextByItsBytesQuotesIncludedUndecoded() {
        String text = "\"v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3 # \\\"é\\\"\"";
        String scene = "{\"objects\": [{\"type\": \"mesh\", \"obj\": " + text + " ,\n \"scale\": 2},"
                + " {\"type\": \"mesh\", \"position\": [1, 2, 3], \"obj\":" + text + "}]}";
        byte[] bytes = scene.getBytes(StandardCharsets.UTF_8);

        int[] ranges = ranges(scene);

        assertThat(new String(bytes, ranges[2], ranges[3] - ranges[2], StandardCharsets.UTF_8)).isEqualTo(text);
        assertThat(new String(bytes, ranges[6], ranges[7] - ranges[6], StandardCharsets.UTF_8)).isEqualTo(text);
    }

    @Test
    void nothingUnlessOneArrayOfObjectsInAWellFormedScene() {
        assertThat(ranges("{\"objects\": []}")).isNull();
        assertThat(ranges("{\"lights\": []}")).isNull();
        assertThat(ranges("{\"objects\": [{}, 3]}")).isNull();
        assertThat(ranges("{\"objects\": {\"type\": \"sphere\"}}")).isNull();
        assertThat(ranges("{\"objects\": [{}], \"objects\": [{}]}")).isNull();
        assertThat(ranges("{\"objects\": [{}]}")).containsExactly(13, 15, -1, -1);
        for (String malformed : new String[] {"{\"objects\": [{}]", "{\"objects\": [{}]} {}", "[{\"objects\": [{}]}]"}) {
            assertThatThrownBy(() -> ranges(malformed)).as(malformed).isInstanceOf(InvalidSceneException.class);
        }
    }

    @Test
    void aLiveViewMessageFindsItsScenesObjectsInTheSamePass() {
        String scene = "{\"lights\": [], \"objects\": [{\"type\": \"sphere\"}, {\"type\": \"plane\"}]}";
        byte[] message = ("{\"revision\": 3, \"scene\": " + scene + ", \"width\": 64}").getBytes(StandardCharsets.UTF_8);

        PreviewRequest request = PreviewRequest.parse(message, 2048, 2048);

        assertThat(new String(request.scene(), StandardCharsets.UTF_8)).isEqualTo(scene);
        int[] objects = request.objects();
        assertThat(objects).hasSize(8);
        assertThat(new String(request.scene(), objects[0], objects[1] - objects[0], StandardCharsets.UTF_8))
                .isEqualTo("{\"type\": \"sphere\"}");
        assertThat(new String(request.scene(), objects[4], objects[5] - objects[4], StandardCharsets.UTF_8))
                .isEqualTo("{\"type\": \"plane\"}");
        assertThat(PreviewRequest.parse("{\"revision\": 4, \"scene\": {\"objects\": [1]}}"
                .getBytes(StandardCharsets.UTF_8), 2048, 2048).objects()).isNull();
    }
}
