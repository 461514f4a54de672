// The cell-function unit (docs/grid_board.md, "The cell function"): a stored
// bound into its cell on one axis of the sweep's grid, bit for bit as the
// C++ GridGeometry::cell computes it:
//   cell(v) = 0 for -inf, dims-1 for +inf; else p = fl32(fl32(v - lo) x scale):
//             0 if not p > 0, dims-1 if p >= dims, else floor(p).
// FLOAT = 1: the word is binary32; a NaN word orders with the infinity of its
// sign, as the model's key does (the board never bins a NaN box). FLOAT = 0:
// the word is an unsigned WIDTH-bit code, its value the code rounded to
// binary32 (nearest even; exact up to 24 bits). lo is finite and scale >= 0
// (the grid's origin and scale from the bounds pass; an infinite scale, from
// a subnormal extent, is taken as IEEE takes it). lo, scale and dims hold for
// a whole pass.
//
// Four register stages, one bound a slot (GridConfig::kCellFunctionSlots):
// the value, the difference v - lo, the mantissa product, the cell.
module grid_cell_function #(
    parameter FLOAT = 1,
    parameter WIDTH = 32
) (
    input  wire             clk,
    input  wire             enable,     // low while the pipeline holds
    input  wire [WIDTH-1:0] word,       // the stored bound
    input  wire [31:0]      lo,         // the axis's origin (binary32)
    input  wire [31:0]      scale,      // cells per unit (binary32, >= 0)
    input  wire [8:0]       dims,       // cells a side, 1 to 256
    output reg  [7:0]       cell_index
);
    function automatic [5:0] leading_zeros(input [47:0] x, input integer bits);
        integer k;
        begin
            leading_zeros = bits[5:0];
            for (k = 0; k < bits; k = k + 1) if (x[k]) leading_zeros = bits[5:0] - 6'd1 - k[5:0];
        end
    endfunction

    // Stage 1: the value, and whether the bound is an infinity (or NaN) of either sign.
    reg [31:0] value;
    reg below, above;
    generate
        if (FLOAT != 0) begin : g_float
            always @(posedge clk) if (enable) begin
                below <= word[31] && word[30:23] == 8'hFF;
                above <= !word[31] && word[30:23] == 8'hFF;
                value <= word == 32'h8000_0000 ? 32'b0 : word;  // -0 is +0
            end
        end else begin : g_fixed
            // The code rounded to binary32: its leading one at bit 31, then 24 bits kept.
            reg [31:0] code;
            always @* begin
                code = 0;
                code[WIDTH-1:0] = word;
            end
            wire [5:0] code_zeros = leading_zeros({16'b0, code}, 32);
            wire [31:0] code_norm = code << code_zeros[4:0];
            // Rounding up carries into the exponent field by itself.
            wire [7:0] code_exp = 8'd158 - {2'b0, code_zeros};
            wire round_up = code_norm[7] & ((|code_norm[6:0]) | code_norm[8]);
            always @(posedge clk) if (enable) begin
                below <= 0;
                above <= 0;
                value <= code_norm[31] ? {1'b0, code_exp, code_norm[30:8]} + {31'b0, round_up} : 32'b0;
            end
        end
    endgenerate

    // Stage 2: the offset v - lo.
    wire [31:0] offset;
    grid_float_add subtract (.a(value), .b({~lo[31], lo[30:0]}), .sum(offset));
    reg [31:0] offset_q;
    reg below_2, above_2;
    always @(posedge clk) if (enable) begin
        offset_q <= offset;
        below_2 <= below;
        above_2 <= above;
    end

    // Stage 3: the product's sign, mantissas and exponents, and its special cases.
    wire offset_inf = offset_q[30:23] == 8'hFF;
    wire scale_inf = scale[30:23] == 8'hFF;
    wire offset_zero = offset_q[30:0] == 0;
    wire scale_zero = scale[30:0] == 0;
    wire [7:0] offset_exp = offset_q[30:23] == 0 ? 8'd1 : offset_q[30:23];
    wire [7:0] scale_exp = scale[30:23] == 0 ? 8'd1 : scale[30:23];
    reg [47:0] product;
    reg [8:0] exp_sum;
    reg negative, not_a_number, infinite, below_3, above_3;
    always @(posedge clk) if (enable) begin
        product <= {offset_q[30:23] != 0, offset_q[22:0]} * {scale[30:23] != 0, scale[22:0]};
        exp_sum <= {1'b0, offset_exp} + {1'b0, scale_exp};
        negative <= offset_q[31] ^ scale[31];
        not_a_number <= (offset_inf && scale_zero) || (scale_inf && offset_zero);
        infinite <= offset_inf || scale_inf;
        below_3 <= below_2;
        above_3 <= above_2;
    end

    // Stage 4: the product normalised and rounded (only p >= 1 decides a
    // cell above 0, so a subnormal product needs no denormalising), floored
    // and clamped. p = 1.f x 2^u, u = (47 - zeros) + exp_sum - 300.
    reg [5:0] zeros;
    reg [47:0] norm;
    reg [8:0] top;
    reg signed [11:0] u;
    reg [7:0] whole;
    reg [7:0] next;
    wire [7:0] last = dims[7:0] - 8'd1;   // dims - 1 (dims = 256 wraps to 255)
    always @* begin
        zeros = leading_zeros(product, 48);
        norm = product << zeros;
        // The top nine bits of the rounded 25-bit mantissa: a carry reaches
        // them only through sixteen ones below.
        top = {1'b0, norm[47:40]} + {8'b0, norm[23] & ((|norm[22:0]) | norm[24]) & (&norm[39:24])};
        u = $signed({6'b0, 6'd47 - zeros}) + $signed({3'b0, exp_sum}) - 12'sd300 + $signed({11'b0, top[8]});
        whole = 0;
        if (u >= 0 && u < 8) whole = top[8] ? 8'd1 << u[2:0] : top[7:0] >> (3'd7 - u[2:0]);
        if (below_3) next = 0;
        else if (above_3) next = last;
        else if (not_a_number) next = 0;
        else if (negative) next = 0;               // p < 0, or -0
        else if (infinite) next = last;
        else if (product == 0 || u < 0) next = 0;  // 0 <= p < 1
        else if (u >= 8 || {1'b0, whole} >= dims) next = last;
        else next = whole;
    end
    always @(posedge clk) if (enable) cell_index <= next;
endmodule
