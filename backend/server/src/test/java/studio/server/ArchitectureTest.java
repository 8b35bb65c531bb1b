package studio.server;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.function.Predicate;

import org.junit.jupiter.api.Test;

import studio.engine.scene.Scene;

/**
 * The server's layering, read from the sources' imports and the class files' references
 * ({@link PackageDependencies}): the system package (configuration, problems, memory, shutdown)
 * knows no feature, the features know it; the engine knows nothing of the server, Spring, Jackson or
 * the servlet and validation APIs; the scene packages depend one way (examples -> compiling ->
 * reading -> format), and on no other feature.
 */
class ArchitectureTest {

    private static final String SERVER = "studio.server";
    private static final String SYSTEM = "studio.server.system";
    private static final String SCENE = "studio.server.scene";
    /** What the engine may not use: the server, and the libraries of HTTP, JSON and Spring. */
    private static final List<String> NOT_FOR_THE_ENGINE = List.of(SERVER, "org.springframework",
            "com.fasterxml.jackson", "tools.jackson", "jakarta");

    private static final List<PackageDependencies.Use> SERVER_USES =
            PackageDependencies.of(Path.of("src/main/java"), StudioApplication.class);
    private static final List<PackageDependencies.Use> ENGINE_USES =
            PackageDependencies.of(Path.of("../engine/src/main/java"), Scene.class);

    @Test
    void systemUsesNoFeature() {
        assertThat(uses(SERVER_USES, from -> inPackage(from, SYSTEM),
                to -> inPackage(to, SERVER) && !inPackage(to, SYSTEM)))
                .as("the system package uses a feature (the feature should register itself with system instead)")
                .isEmpty();
    }

    @Test
    void engineUsesNeitherTheServerNorSpringJacksonOrJakarta() {
        assertThat(uses(ENGINE_USES, from -> true, to -> NOT_FOR_THE_ENGINE.stream().anyMatch(p -> inPackage(to, p))))
                .as("the engine uses the server, Spring, Jackson or a jakarta API")
                .isEmpty();
    }

    @Test
    void scenePackagesFormNoCycle() {
        Map<String, Set<String>> edges = new TreeMap<>();
        for (PackageDependencies.Use use : SERVER_USES) {
            String from = PackageDependencies.packageOf(use.from());
            String to = PackageDependencies.packageOf(use.to());
            if (inPackage(from, SCENE) && inPackage(to, SCENE) && !from.equals(to)) {
                edges.computeIfAbsent(from, k -> new TreeSet<>()).add(to);
            }
        }
        assertThat(edges).as("the scene packages depend on each other").isNotEmpty();
        assertThat(PackageDependencies.cycle(edges)).as("a cycle among the scene packages").isNull();
    }

    @Test
    void sceneUsesNoOtherFeature() {
        assertThat(uses(SERVER_USES, from -> inPackage(from, SCENE),
                to -> inPackage(to, SERVER) && !inPackage(to, SCENE) && !inPackage(to, SYSTEM)))
                .as("the scene packages use another feature")
                .isEmpty();
    }

    /** So that the rules above cannot pass for want of reading anything. */
    @Test
    void readsBothWitnessesOfBothModules() {
        for (List<PackageDependencies.Use> uses : List.of(SERVER_USES, ENGINE_USES)) {
            assertThat(uses).extracting(PackageDependencies.Use::how).contains("import", "class file");
        }
        assertThat(uses(SERVER_USES, from -> inPackage(from, SYSTEM), to -> inPackage(to, "org.springframework")))
                .isNotEmpty();
    }

    @Test
    void findsACycleWhereThereIsOne() {
        Map<String, Set<String>> cyclic = new TreeMap<>(Map.of("a", Set.of("b"), "b", Set.of("c"), "c", Set.of("a")));
        assertThat(PackageDependencies.cycle(cyclic)).containsExactly("a", "b", "c", "a");
        assertThat(PackageDependencies.cycle(new TreeMap<>(Map.of("a", Set.of("b"), "b", Set.of("c"))))).isNull();
    }

    /** The uses from classes matching {@code from} of classes matching {@code to}. */
    private static List<String> uses(List<PackageDependencies.Use> all, Predicate<String> from, Predicate<String> to) {
        return all.stream().filter(u -> from.test(PackageDependencies.packageOf(u.from())) && to.test(u.to()))
                .map(PackageDependencies.Use::toString).distinct().toList();
    }

    /** Whether a class or package name is in {@code pkg} or one of its sub-packages. */
    private static boolean inPackage(String name, String pkg) {
        return name.equals(pkg) || name.startsWith(pkg + ".");
    }
}
