package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.concurrent.FutureTask;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

import studio.server.Await;

class MemoryBudgetTest {

    @Test
    void reservesWhatIsFreeAndRefusesTheRest() {
        MemoryBudget budget = new MemoryBudget(100);
        MemoryBudget.Reservation sixty = budget.tryReserve(60);
        assertThat(sixty).isNotNull();
        assertThat(budget.tryReserve(41)).isNull();
        MemoryBudget.Reservation forty = budget.tryReserve(40);
        assertThat(forty).isNotNull();
        assertThat(budget.reserved()).isEqualTo(100);
        sixty.close();
        sixty.close(); // twice gives back once
        assertThat(budget.reserved()).isEqualTo(40);
        forty.close();
        assertThat(budget.reserved()).isZero();
    }

    @Test
    void keptThingsGiveTheirMemoryBackOldestFirstWhenWorkNeedsIt() {
        MemoryBudget budget = new MemoryBudget(100);
        java.util.List<String> dropped = new java.util.ArrayList<>();
        MemoryBudget.Reservation scene = budget.tryReserveYielding(30, () -> dropped.add("scene"));
        MemoryBudget.Reservation film = budget.tryReserveYielding(40, () -> dropped.add("film"));
        assertThat(budget.tryReserveYielding(31, () -> dropped.add("more"))).as("kept things take no kept memory")
                .isNull();
        assertThat(budget.yieldingCount()).isEqualTo(2);

        MemoryBudget.Reservation work = budget.tryReserve(50); // 30 free: the oldest gives way, then enough
        assertThat(work).isNotNull();
        assertThat(dropped).containsExactly("scene");
        assertThat(budget.reserved()).isEqualTo(90);
        scene.close(); // its holder closing it too gives back nothing twice
        assertThat(budget.reserved()).isEqualTo(90);

        MemoryBudget.Reservation grown = budget.tryReserve(0);
        assertThat(grown.tryGrow(10)).isTrue();
        assertThat(dropped).containsExactly("scene");
        assertThat(grown.tryGrow(40)).isTrue(); // only by taking the film back
        assertThat(dropped).containsExactly("scene", "film");
        assertThat(budget.yieldingCount()).isZero();
        assertThat(budget.tryReserve(1)).as("nothing kept is left to give").isNull();
        film.close();
        work.close();
        grown.close();
        assertThat(budget.reserved()).isZero();
    }

    @Test
    void aHandOverAndAWaitTakeKeptMemoryBackToo() throws Exception {
        MemoryBudget budget = new MemoryBudget(100);
        MemoryBudget.Reservation kept = budget.tryReserveYielding(60, () -> { });
        MemoryBudget.Reservation body = budget.tryReserve(30);
        MemoryBudget.Reservation render = body.tryHandOver(60, 0); // 30 freed, 10 free: needs the kept 60
        assertThat(render).isNotNull();
        assertThat(budget.reserved()).isEqualTo(60);
        render.close();
        MemoryBudget.Reservation kept2 = budget.tryReserveYielding(70, () -> { });
        MemoryBudget.Reservation growing = budget.tryReserve(20);
        assertThat(growing.growOrWait(50, Duration.ofMillis(100))).isTrue();
        assertThat(budget.yieldingCount()).isZero();
        growing.close();
        kept.close();
        kept2.close();
        assertThat(budget.reserved()).isZero();
    }

    @Test
    void forcedReservationMayGoBeyondTheBudgetAndBlocksNewWork() {
        MemoryBudget budget = new MemoryBudget(100);
        MemoryBudget.Reservation image = budget.forceReserve(150);
        assertThat(budget.tryReserve(1)).isNull();
        image.close();
        assertThat(budget.tryReserve(100)).isNotNull();
    }

    @Test
    void refusesNonsense() {
        assertThatThrownBy(() -> new MemoryBudget(0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new MemoryBudget(10).tryReserve(-1)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> MemoryBudget.ofHeapShare(1.5)).isInstanceOf(IllegalArgumentException.class);
        assertThat(MemoryBudget.ofHeapShare(0.5).capacity()).isEqualTo(Runtime.getRuntime().maxMemory() / 2);
    }

    @Test
    void growsWhileTheRestCoversItAndGivesAllBackOnClose() {
        MemoryBudget budget = new MemoryBudget(100);
        MemoryBudget.Reservation growing = budget.tryReserve(0);
        assertThat(growing.tryGrow(70)).isTrue();
        MemoryBudget.Reservation other = budget.tryReserve(20);
        assertThat(growing.tryGrow(11)).as("beyond the budget").isFalse();
        assertThat(growing.bytes()).isEqualTo(70);
        assertThat(growing.tryGrow(10)).isTrue();
        assertThat(budget.reserved()).isEqualTo(100);
        growing.close();
        other.close();
        assertThat(budget.reserved()).isZero();
    }

    @Test
    void handsOverInOneStepKeepingWhatItIsToldTo() {
        MemoryBudget budget = new MemoryBudget(100);
        MemoryBudget.Reservation compile = budget.tryReserve(80);
        // 80 held, 20 free: 90 more fit only because the compile gives back all but 10 in the same step
        MemoryBudget.Reservation render = compile.tryHandOver(90, 10);
        assertThat(render).isNotNull();
        assertThat(render.bytes()).isEqualTo(90);
        assertThat(compile.bytes()).isEqualTo(10);
        assertThat(budget.reserved()).isEqualTo(100);
        assertThat(compile.tryHandOver(1, 10)).as("nothing left to give").isNull();
        assertThat(compile.bytes()).as("unchanged when refused").isEqualTo(10);
        compile.close();
        render.close();
        assertThat(budget.reserved()).isZero();
    }

    @Test
    void oneReservationWaitsForMemoryWhileOthersAreRefusedAtOnce() throws Exception {
        MemoryBudget budget = new MemoryBudget(100);
        MemoryBudget.Reservation render = budget.tryReserve(60);
        MemoryBudget.Reservation first = budget.tryReserve(10);
        MemoryBudget.Reservation second = budget.tryReserve(0);
        FutureTask<Boolean> waited = new FutureTask<>(() -> first.growOrWait(50, Duration.ofSeconds(30)));
        Thread waiting = new Thread(waited, "waiting for memory");
        waiting.start();
        Await.until("the first to wait", 10_000, () -> waiting.getState() == Thread.State.TIMED_WAITING);

        assertThat(second.tryGrow(25)).as("30 free, but the waiter needs 50 of them").isFalse();
        assertThat(budget.tryReserve(25)).isNull();
        assertThat(second.growOrWait(1, Duration.ofSeconds(30))).as("one waits at a time").isFalse();
        render.close();

        assertThat(waited.get(10, TimeUnit.SECONDS)).isTrue();
        assertThat(first.bytes()).isEqualTo(60);
        assertThat(second.tryGrow(40)).as("no one waits: nothing is held back for a waiter").isTrue();
    }

    @Test
    void aWaitEndsAtItsBoundHoldingWhatItHeld() {
        MemoryBudget budget = new MemoryBudget(100);
        MemoryBudget.Reservation other = budget.tryReserve(60);
        MemoryBudget.Reservation growing = budget.tryReserve(10);
        long start = System.nanoTime();

        assertThat(growing.growOrWait(50, Duration.ofMillis(200))).isFalse();

        assertThat((System.nanoTime() - start) / 1_000_000).isBetween(150L, 5_000L);
        assertThat(growing.bytes()).isEqualTo(10);
        assertThat(growing.growOrWait(91, Duration.ofSeconds(30))).as("could never fit: no wait").isFalse();
        assertThat(other.tryGrow(30)).as("no one waits: the 30 free are not held back").isTrue();
        other.close();
    }
}
