package studio.server.preview;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

import studio.server.scene.compiling.CompiledScene;

/**
 * A live view's scene reader that notes how many objects each scene it reads holds: a revision
 * read in full reads a scene with all of its objects, one assembled from the kept scene reads only
 * its changed objects, each alone.
 */
final class CountedReads implements Function<byte[], CompiledScene> {

    private final Function<byte[], CompiledScene> read;
    private final List<Integer> objects = new ArrayList<>();

    CountedReads(Function<byte[], CompiledScene> read) {
        this.read = read;
    }

    @Override
    public CompiledScene apply(byte[] json) {
        CompiledScene scene = read.apply(json);
        objects.add(scene.scene().objectCount());
        return scene;
    }

    /** Scenes read so far. */
    int reads() {
        return objects.size();
    }

    /** Scenes read from the {@code from}-th on that held {@code count} objects or more. */
    long holding(int count, int from) {
        return objects.subList(from, objects.size()).stream().filter(n -> n >= count).count();
    }

    /** Scenes read so far that held {@code count} objects or more: the whole scenes, for a scene of that many. */
    long holding(int count) {
        return holding(count, 0);
    }
}
