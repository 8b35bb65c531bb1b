package studio.server.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;

import org.junit.jupiter.api.Test;

import studio.server.scene.examples.ExampleSceneFiles;
import studio.server.system.MemoryBudget;

class RenderWarmUpTest {

    private final RenderBudget budget = new RenderBudget(Duration.ofMinutes(5), new MemoryBudget(256L << 20));

    @Test
    void rendersEveryTrainingSceneInTheJarMeshesIncluded() {
        RenderWarmUp.Outcome outcome = new RenderWarmUp(ExampleSceneFiles.compiler(), budget, 1, Duration.ofMinutes(2)).run();

        assertEquals(4, outcome.scenes(), "bin/training's four scenes are packaged under training/");
        assertEquals(outcome.scenes(), outcome.rendered(), "every scene read, mapped and rendered, knot.obj included");
    }

    @Test
    void stopsAtItsLimitWithoutFailingTheStart() {
        RenderWarmUp.Outcome outcome = new RenderWarmUp(ExampleSceneFiles.compiler(), budget, 1, Duration.ofNanos(1)).run();

        assertEquals(0, outcome.rendered());
        assertTrue(outcome.scenes() > 0);
    }

    @Test
    void rendersNothingWhileOtherWorkHoldsTheRenderMemory() {
        MemoryBudget memory = new MemoryBudget(256L << 20);
        try (MemoryBudget.Reservation taken = memory.tryReserve(memory.capacity())) {
            RenderWarmUp.Outcome outcome = new RenderWarmUp(ExampleSceneFiles.compiler(),
                    new RenderBudget(Duration.ofMinutes(5), memory), 1, Duration.ofMinutes(2)).run();

            assertEquals(0, outcome.rendered(), "no scene rendered without its memory reserved first");
            assertEquals(4, outcome.scenes());
        }
        assertEquals(0, memory.reserved(), "and nothing left reserved");
    }

    @Test
    void zeroTurnsItOff() {
        // a warm-up that ran would need its compiler and budget: with none, only "off" gets through
        new RenderWarmUp(null, null, 1, Duration.ZERO).afterSingletonsInstantiated();
    }
}
