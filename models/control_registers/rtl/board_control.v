// The board's controller: one state per phase, as the model's phase
// variable (idle, sweeping, draining, paused on a full pair buffer, done),
// the cycle and stall counters the host reads, and the interrupt.
module board_control #(
    parameter CW = 32,       // counter bits
    // 1: the whole board's controller (models/board/rtl): ABORT returns to
    // idle, a pause after the last address resumes into the drain, and the
    // board is done on the edge the pipeline empties after the last address
    // even if that edge would move SWEEP to DRAIN, as the C++ model. 0: the
    // piece as the resource model's table synthesised it (abort unused).
    parameter MODEL_TIMING = 0
) (
    input  wire          clk,
    input  wire          abort,          // host writes ABORT (or reset): back to idle
    input  wire          start,          // host writes START
    input  wire          resume,         // host writes RESUME after draining the buffer
    input  wire          sweeping,       // the address generator has addresses
    input  wire          pipeline_empty, // no hits in flight, FIFO empty
    input  wire          fifo_room,
    input  wire          buffer_full,    // a pair must move while the buffer is full
    output wire          enable,         // the datapath advances this cycle
    output reg  [4:0]    state,          // one-hot: idle, sweep, drain, paused, done
    output reg  [CW-1:0] cycles,
    output reg  [CW-1:0] stalls,
    output wire          irq
);
    localparam IDLE = 0, SWEEP = 1, DRAIN = 2, PAUSED = 3, DONE = 4;
    wire running = state[SWEEP] | state[DRAIN];
    assign enable = running & fifo_room & ~buffer_full;
    assign irq = state[DONE] | state[PAUSED];
    always @(posedge clk) begin
        if (MODEL_TIMING && abort) begin
            state <= 5'b1 << IDLE;
        end else if (start) begin
            state <= 5'b1 << SWEEP;
            cycles <= 0;
            stalls <= 0;
        end else begin
            if (running) begin
                cycles <= cycles + 1;
                if (!enable) stalls <= stalls + 1;
            end
            if (running && buffer_full) state <= 5'b1 << PAUSED;
            else if (MODEL_TIMING && state[PAUSED] && resume) state <= 5'b1 << (sweeping ? SWEEP : DRAIN);
            else if (state[PAUSED] && resume) state <= 5'b1 << SWEEP;
            else if (MODEL_TIMING && running && !sweeping && pipeline_empty) state <= 5'b1 << DONE;
            else if (state[SWEEP] && !sweeping) state <= 5'b1 << DRAIN;
            else if (!MODEL_TIMING && state[DRAIN] && pipeline_empty) state <= 5'b1 << DONE;
            else if (state == 0) state <= 5'b1 << IDLE;
        end
    end
endmodule
