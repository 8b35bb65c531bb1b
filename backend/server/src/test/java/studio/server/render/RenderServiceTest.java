package studio.server.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import studio.server.Await;
import studio.server.scene.examples.ExampleSceneFiles;
import studio.server.scene.format.InvalidSceneException;
import studio.server.system.MemoryBudget;

/** The synchronous render service without HTTP: its slots, its time budget, and what a refused request costs. */
class RenderServiceTest {

    /** One 16 x 16 tile that takes several seconds on one thread. */
    private static final byte[] ONE_SLOW_TILE = HallOfGlass.scene(16, 256).getBytes(StandardCharsets.UTF_8);
    private static final byte[] NOT_A_SCENE = "{\"objects\": [{\"type\": \"teapot\"}]}"
            .getBytes(StandardCharsets.UTF_8);

    private final MemoryBudget memory = new MemoryBudget(256L << 20);
    private RenderService renders;

    @AfterEach
    void stop() throws Exception {
        renders.close();
        Await.until("the memory to be given back", 10_000, () -> memory.reserved() == 0);
    }

    /** As for jobs: the slot is checked before the scene is read, so a refusal costs no reading. */
    @Test
    void aRequestWithNoFreeSlotIsRefusedBeforeItsSceneIsRead() throws Exception {
        renders = new RenderService(ExampleSceneFiles.compiler(), 1, 1,
                new RenderBudget(Duration.ofMinutes(5), memory));
        RenderService.Ticket busy = renders.start(ONE_SLOW_TILE);

        assertThrows(RenderBusyException.class, () -> renders.start(NOT_A_SCENE));

        busy.cancel();
        Await.until("the slot to be free", 10_000, () -> renders.active() == 0);
        assertThrows(InvalidSceneException.class, () -> renders.start(NOT_A_SCENE));
        assertEquals(0, renders.active(), "an invalid scene gives its slot back");
    }

    /** Else a client that asks again as soon as it has its image can be refused for the render it already has. */
    @Test
    void aRenderIsAnsweredOnlyOnceItsSlotAndMemoryAreFree() throws Exception {
        renders = new RenderService(ExampleSceneFiles.compiler(), 1, 1, new RenderBudget(Duration.ofMinutes(5), memory));
        RenderService.Ticket ticket = renders.start(HallOfGlass.scene(16, 16).getBytes(StandardCharsets.UTF_8));
        CompletableFuture<String> seenOnAnswer = ticket.result()
                .thenApply(image -> "slots in use " + renders.active() + ", memory held " + memory.reserved());
        assertFalse(ticket.result().isDone(), "the render (about 0.4 s) ended before the test could look");

        assertEquals("slots in use 0, memory held 0", seenOnAnswer.get(30, TimeUnit.SECONDS));
    }

    @Test
    void aRenderOverItsTimeBudgetInItsOnlyTileFailsWithinASecondOfItsDeadline() throws Exception {
        long budgetMillis = 300;
        renders = new RenderService(ExampleSceneFiles.compiler(), 1, 1,
                new RenderBudget(Duration.ofMillis(budgetMillis), memory));
        long start = System.nanoTime();
        RenderService.Ticket ticket = renders.start(ONE_SLOW_TILE);

        ExecutionException failed = assertThrows(ExecutionException.class,
                () -> ticket.result().get(30, TimeUnit.SECONDS));

        long millis = (System.nanoTime() - start) / 1_000_000;
        assertInstanceOf(RenderTimeExceededException.class, failed.getCause());
        assertTrue(millis < budgetMillis + 1_000, "the render ended " + millis + " ms after it started");
    }
}
