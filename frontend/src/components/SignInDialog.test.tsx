import { act, render, screen, waitFor } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { describe, expect, it } from 'vitest';
import { apiKey, authorizedFetch } from '../api/auth';
import { SignInDialog } from './SignInDialog';
import { SignInStatus } from './SignInStatus';

const unauthorized = () => new Response('{}', { status: 401, headers: { 'Content-Type': 'application/problem+json' } });
const meAs = (principal: string, signInRequired: boolean) =>
  new Response(JSON.stringify({ principal, signInRequired }), { headers: { 'Content-Type': 'application/json' } });

/** A server with sign-in on that knows one key, `k-alice`, as alice. */
const server = async (_url: string, init?: RequestInit) =>
  new Headers(init?.headers).get('Authorization') === 'Bearer k-alice' ? meAs('alice', true) : unauthorized();

describe('SignInDialog', () => {
  it('shows nothing until the server asks for a key', () => {
    render(<SignInDialog />);
    expect(screen.queryByRole('dialog')).toBeNull();
  });

  it('asks for a key on 401, signs in with it, and shows who is signed in', async () => {
    const user = userEvent.setup();
    render(
      <>
        <SignInDialog />
        <SignInStatus fetchFn={authorizedFetch(server)} />
      </>,
    );
    const dialog = await screen.findByRole('dialog', { name: 'Sign in' });
    const field = screen.getByLabelText('API key');
    expect(field).toHaveFocus();
    expect(field).toHaveAttribute('type', 'password');
    await user.type(field, 'k-alice');
    await user.click(screen.getByRole('button', { name: 'Sign in' }));

    expect(await screen.findByText('Signed in as alice')).toBeInTheDocument();
    expect(dialog).not.toBeInTheDocument();
    expect(apiKey()).toBe('k-alice');

    await user.click(screen.getByRole('button', { name: 'Sign out' }));
    expect(apiKey()).toBeNull();
    expect(await screen.findByRole('dialog', { name: 'Sign in' })).toBeInTheDocument();
  });

  it('Escape cancels: the request fails as refused and no key is kept', async () => {
    const user = userEvent.setup();
    render(<SignInDialog />);
    let status = 0;
    act(() => {
      void authorizedFetch(async () => unauthorized())('/api/scenes').then((r) => (status = r.status));
    });
    await screen.findByRole('dialog', { name: 'Sign in' });
    await user.keyboard('{Escape}');
    await waitFor(() => expect(status).toBe(401));
    expect(screen.queryByRole('dialog')).toBeNull();
    expect(apiKey()).toBeNull();
  });
});

describe('SignInStatus', () => {
  it('shows nothing with sign-in off', async () => {
    let asked = false;
    render(
      <SignInStatus
        fetchFn={async () => {
          asked = true;
          return meAs('', false);
        }}
      />,
    );
    await waitFor(() => expect(asked).toBe(true));
    expect(screen.queryByText(/Signed in/)).toBeNull();
    expect(screen.queryByRole('button', { name: 'Sign out' })).toBeNull();
  });
});
