package studio.server.asset;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

import studio.server.system.MemoryBudget;

class LocalAssetsTest {

    private static Asset asset(int size, int seed) {
        byte[] bytes = new byte[size];
        bytes[0] = (byte) seed;
        return Asset.of(AssetType.OBJ, bytes);
    }

    @Test
    void dropsTheLeastRecentlyUsedAssetToMakeRoom() {
        MemoryBudget budget = new MemoryBudget(1_000);
        LocalAssets store = new LocalAssets(100, budget);
        Asset a = asset(40, 1), b = asset(40, 2), c = asset(40, 3);
        assertThat(store.put(a)).isTrue();
        assertThat(store.put(b)).isTrue();
        assertThat(store.get(a.id())).isSameAs(a); // a is now the most recently used
        assertThat(store.put(c)).isTrue();

        assertThat(store.contains(a.id())).isTrue();
        assertThat(store.contains(b.id())).isFalse();
        assertThat(store.contains(c.id())).isTrue();
        assertThat(store.bytes()).isEqualTo(80);
        assertThat(budget.reserved()).isEqualTo(80);
    }

    @Test
    void keepsTheSameBytesOnce() {
        MemoryBudget budget = new MemoryBudget(1_000);
        LocalAssets store = new LocalAssets(100, budget);
        assertThat(store.put(asset(40, 1))).isTrue();
        assertThat(store.put(asset(40, 1))).isFalse();
        assertThat(budget.reserved()).isEqualTo(40);
    }

    @Test
    void dropsAssetsWhenTheMemoryBudgetIsShortAndRefusesWithRetryAfterWhenThatIsNotEnough() {
        MemoryBudget budget = new MemoryBudget(100);
        LocalAssets store = new LocalAssets(100, budget);
        Asset a = asset(30, 1);
        store.put(a);
        MemoryBudget.Reservation render = budget.tryReserve(50); // a render holds half the budget
        Asset b = asset(40, 2);
        store.put(b); // room only once a is dropped
        assertThat(store.contains(a.id())).isFalse();
        assertThat(store.contains(b.id())).isTrue();

        assertThatThrownBy(() -> store.put(asset(60, 3)))
                .isInstanceOfSatisfying(AssetRefusedException.class, e -> {
                    assertThat(e.getStatusCode().value()).isEqualTo(503);
                    assertThat(e.getHeaders().getFirst("Retry-After")).isEqualTo("5");
                });
        render.close();
        assertThat(budget.reserved()).isZero(); // b was dropped trying; nothing is held for a refused asset
        assertThat(store.bytes()).isZero();
    }
}
