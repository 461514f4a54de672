// One comparison lane: box i (port 0) against box j (port k), six
// comparators ANDed: min_i <= max_j and min_j <= max_i on x, y and z.
// Bounds are packed min_x, min_y, min_z, max_x, max_y, max_z, each WIDTH
// bits, lowest first. FLOAT = 1: IEEE binary32 comparators (float_le);
// FLOAT = 0: unsigned WIDTH-bit fixed point, quantised outward by the host.
// LATENCY register stages from the block RAM outputs to 'hit' (the model's
// compare latency): the first registers the six comparator results, the
// second their AND, any further ones delay it.
module compare_lane #(
    parameter FLOAT = 1,
    parameter WIDTH = 32,
    parameter LATENCY = 2
) (
    input  wire               clk,
    input  wire               enable,    // low while the pipeline holds (back-pressure)
    input  wire               valid_in,  // the lane's port holds a box this cycle
    input  wire [6*WIDTH-1:0] box_i,
    input  wire [6*WIDTH-1:0] box_j,
    output wire               hit,
    // What hit becomes at the next edge with enable: from registers at
    // LATENCY 2 and more (the stage before hit), so a count of the lanes'
    // hits can be made a cycle ahead (the pair FIFO's); at LATENCY 0 it is
    // hit itself.
    output wire               hit_next
);
    wire [5:0] le;
    genvar axis;
    generate
        for (axis = 0; axis < 3; axis = axis + 1) begin : g_axis
            wire [WIDTH-1:0] min_i = box_i[axis*WIDTH +: WIDTH];
            wire [WIDTH-1:0] max_i = box_i[(axis+3)*WIDTH +: WIDTH];
            wire [WIDTH-1:0] min_j = box_j[axis*WIDTH +: WIDTH];
            wire [WIDTH-1:0] max_j = box_j[(axis+3)*WIDTH +: WIDTH];
            if (FLOAT != 0) begin : g_float
                float_le i_le_j (.a(min_i), .b(max_j), .le(le[2*axis]));
                float_le j_le_i (.a(min_j), .b(max_i), .le(le[2*axis+1]));
            end else begin : g_fixed
                assign le[2*axis]   = min_i <= max_j;
                assign le[2*axis+1] = min_j <= max_i;
            end
        end
    endgenerate

    wire [6:0] stage0 = {valid_in, le};
    generate
        if (LATENCY == 0) begin : g_comb
            assign hit = valid_in & (&le);
            assign hit_next = hit;
        end else begin : g_piped
            reg [6:0] compared;  // stage 1: comparator results and valid
            reg [LATENCY-1:0] anded;  // stage 2 onwards: the AND, delayed
            always @(posedge clk) if (enable) compared <= stage0;
            integer s;
            always @(posedge clk) if (enable) begin
                anded[0] <= compared[6] & (&compared[5:0]);
                for (s = 1; s < LATENCY; s = s + 1) anded[s] <= anded[s-1];
            end
            assign hit = (LATENCY == 1) ? (compared[6] & (&compared[5:0])) : anded[LATENCY-2];
            if (LATENCY == 1) begin : g_next_compared
                assign hit_next = valid_in & (&le);
            end else if (LATENCY == 2) begin : g_next_anded
                assign hit_next = compared[6] & (&compared[5:0]);
            end else begin : g_next_delayed
                assign hit_next = anded[LATENCY-3];
            end
        end
    endgenerate
endmodule
